// G-buffer layout (docs/screen-space.md):
//   depth/stencil  D24S8; stencil = SSS profile slot of the draw (0 = opaque), for the blurs
//   target 0       RGBA16F: linear albedo, a = object id / 255
//   target 1       RGBA16F: xy octahedral view-space normal, z roughness m, w rho_s (include/Material.glsl)
//   target 2       R32UI: profile slot and view depth packed, the key that
//                  depth-aware blurs compare (layout in UniformBlocks.glsl)
//   target 3       RGBA16F: the scattering share s, the KHR_materials_volume
//                  thickness in mm (DERMIS_GBUFFER_SCATTER_LOCATION, docs/materials.md)
//                  the surface's curvature in 1/mm (0 unless some slot
//                  scatters in the lighting pass) and the profile slot
//                  (include/LightingScatter.glsl reads both)
// With GBUFFER_LEAN defined (variants lcb and lbb, plan/SssVariant.h):
//   target 4       RGBA16F: LEAN (B'.x, B'.y, M'.xx, M'.yy) on the view plane
//   target 5       R16F: LEAN M'.xy
//   (include/Lean.glsl: the space, the projection and the packing). The
//   normal is then the LEAN mean normal, so the normal map is not read.
// With GBUFFER_TRANSFER defined as the next free target (4, or 6 with LEAN),
// when the environment's occlusion is "transfer" (include/EnvironmentTransfer.glsl):
//   target N       RGBA16F: the environment irradiance L.T interpolated from
//                  the vertices, a = the share of the sky they see
// Material maps are sampled with the mip bias uFrame.materialMipBias (0 but in tests).
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Material.glsl"
#ifdef GBUFFER_LEAN
#include "Lean.glsl"
#endif

layout(binding = 0) uniform sampler2D uAlbedoMap;
layout(binding = 1) uniform sampler2D uNormalMap;
layout(binding = DERMIS_UNIT_SCATTER_MAP) uniform sampler2D uScatterMap;
layout(binding = DERMIS_UNIT_THICKNESS_MAP) uniform sampler2D uThicknessMap;
#ifdef GBUFFER_LEAN
layout(binding = 2) uniform sampler2D uLean1;  // (B.x, B.y, M.xx, M.yy), tangent space
layout(binding = 3) uniform sampler2D uLean2;  // (M.xy, base variance)
#endif

in vec3 vViewNormal;
in vec4 vViewTangent;
in vec2 vUv;
#ifndef GBUFFER_VERTEX_COLOUR
#define GBUFFER_VERTEX_COLOUR 1  // gbuffer.vert says what it is
#endif
#if GBUFFER_VERTEX_COLOUR
in vec3 vColour;
#else
const vec3 vColour = vec3(1.0);
#endif

layout(location = 0) out vec4 oAlbedo;
layout(location = 1) out vec4 oNormalMaterial;
layout(location = 2) out uint oDepthKey;
layout(location = DERMIS_GBUFFER_SCATTER_LOCATION) out vec4 oScatter;
#ifdef GBUFFER_LEAN
layout(location = 4) out vec4 oLeanMoments;
layout(location = 5) out float oLeanCross;
#endif
#ifdef GBUFFER_TRANSFER
in vec4 vEnvironment;
layout(location = GBUFFER_TRANSFER) out vec4 oEnvironment;
#endif

in vec3 vViewPositionM;

// The tangent frame (columns T, B, N) around the geometric normal N.
mat3 tangentFrame(vec3 N) {
    vec3 T = vViewTangent.xyz - N * dot(N, vViewTangent.xyz);
    T = safeNormalize(T, abs(N.x) < 0.9 ? normalize(cross(N, vec3(1, 0, 0))) : normalize(cross(N, vec3(0, 1, 0))));
    vec3 B = cross(N, T) * (vViewTangent.w < 0.0 ? -1.0 : 1.0);
    return mat3(T, B, N);
}

// |dN| / |dP| across the pixel of the interpolated vertex normal: 1/r on a
// sphere of radius r, whatever the direction (Penner & Borshukov 2011).
float curvaturePerMm() {
    // The normalised normal's change: the interpolated one's, less its part along
    // the normal, over its length (written out: llvmpipe's LLVM 15 crashed on
    // dFdx(safeNormalize(...)) here).
    float lengthN = max(length(vViewNormal), 1e-8);
    vec3 N = vViewNormal / lengthN;
    vec3 dNdx = dFdx(vViewNormal);
    vec3 dNdy = dFdy(vViewNormal);
    dNdx -= N * dot(N, dNdx);
    dNdy -= N * dot(N, dNdy);
    vec3 dPdx = dFdx(vViewPositionM);
    vec3 dPdy = dFdy(vViewPositionM);
    float normalChange = sqrt(dot(dNdx, dNdx) + dot(dNdy, dNdy)) / lengthN;
    float positionChangeMm = 1000.0 * sqrt(dot(dPdx, dPdx) + dot(dPdy, dPdy));
    return positionChangeMm > 0.0 ? normalChange / positionChangeMm : 0.0;
}

void main() {
    float mipBias = uFrame.materialMipBias;
    MapFootprint at = pixelFootprint(vUv, mipBias);
    vec3 albedo = materialAlbedo(uAlbedoMap, at, vColour);
    bool hasMaps = uObject.hasNormalMap > 0.5;
    float roughness = materialRoughness(at);

    vec3 N = safeNormalize(vViewNormal, vec3(0.0, 0.0, 1.0));
    if (!gl_FrontFacing) N = -N;
#ifdef GBUFFER_LEAN
    mat3 TBN = tangentFrame(N);
    vec2 bump = vec2(0.0);
    vec3 moments = vec3(0.0);
    // Beckmann m as a slope variance per axis, m^2 / 2 (Lean.glsl).
    float baseVariance = 0.5 * roughness * roughness;
    if (hasMaps) {
        vec4 lean1 = readMap(uLean1, at);
        vec2 lean2 = readMap(uLean2, at).xy;
        bump = lean1.xy;
        moments = vec3(lean1.zw, lean2.x);
        baseVariance += lean2.y;
        N = safeNormalize(leanMeanNormal(bump, TBN), N);
    }
    vec2 viewBump;
    vec3 viewMoments;
    leanProject(bump, moments, baseVariance, TBN, safeNormalize(-vViewPositionM, vec3(0.0, 0.0, 1.0)), viewBump,
                viewMoments);
    oLeanMoments = vec4(viewBump, viewMoments.xy);
    oLeanCross = viewMoments.z;
#else
    if (hasMaps) {
        vec3 tangentNormal = readMap(uNormalMap, at).xyz * 2.0 - 1.0;
        N = safeNormalize(tangentFrame(N) * tangentNormal, N);
    }
#endif

    oAlbedo = debugPlant(vec4(albedo, uObject.objectId / 255.0));
    oNormalMaterial = vec4(encodeNormal(N), roughness, materialRhoS(at));
    int slot = int(uObject.profileSlot + 0.5);
    oDepthKey = makeDepthKey(slot, -vViewPositionM.z);
    float scatter = uObject.scatteringShare * (uObject.hasScatterMap > 0.5 ? readMap(uScatterMap, at).r : 1.0);
    float thicknessMm = uObject.thicknessMm * (uObject.hasThicknessMap > 0.5 ? readMap(uThicknessMap, at).r : 1.0);
    // The curvature only for frames that read it (a uniform branch).
    float curvature = uProfiles.anyScattersInLighting != 0 ? curvaturePerMm() : 0.0;
    oScatter = vec4(slot > 0 ? clamp(scatter, 0.0, 1.0) : 0.0, max(thicknessMm, 0.0), curvature, float(slot));
#ifdef GBUFFER_TRANSFER
    oEnvironment = vEnvironment;
#endif
}
