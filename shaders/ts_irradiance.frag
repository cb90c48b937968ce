// Texture-space step 2: the irradiance texture (Chappuis 2011 §2.2.3, include/TextureSpace.glsl).
//   rgb: sum over lights of radiance x N.L x PCF shadow x (1 - rho_s rho_dt(N.L, m))
//        (Chappuis 2011 §2.4, §2.6), plus ambient x SSAO (where the texel is the
//        pixel the camera sees), plus the environment's diffuse light with
//        its occlusion (include/Environment.glsl), times albedo^mix
//        (pre-scatter, §2.2.4): the same light the lighting pass gives a
//        pixel (lighting.frag).
//   a:   exp(-c d), d the thickness (mm) towards the TSM light (listing 2.7),
//        1 without a TSM; always > 0, so 0 marks an empty texel.
//   Texels of surface inside the body (mesh/UvLayout.h buried) stay empty,
//   except in the capture for the reference (uBuriedEmpty 0).
// The material's maps (normal, albedo, roughness, rho_s) are read at the mip
// level of the pixel that shows the point, not at the texel's own: a texel
// holds the light the lighting pass gives that point, and both modes (and
// the matched reference, which captures this texture: docs/reference.md)
// scatter the same light. cameraFootprint() below.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"
#include "Lights.glsl"
#include "EnergyConservation.glsl"
#include "Environment.glsl"
#include "TextureSpace.glsl"
#include "Material.glsl"
#include "Lean.glsl"

layout(binding = 0) uniform sampler2D uAlbedoMap;
layout(binding = 1) uniform sampler2D uNormalMap;
layout(binding = 2) uniform sampler2D uTsm;
layout(binding = 3) uniform sampler2D uAmbientOcclusion;  // screen space; 1x1 when SSAO is off
layout(binding = 4) uniform sampler2D uShadowMaps[DERMIS_MAX_SHADOWED_LIGHTS];
layout(binding = 8) uniform usampler2D uDepthKey;         // G-buffer target 2
layout(binding = DERMIS_UNIT_ENERGY) uniform sampler2D uEnergy;
// The frames whose G-buffer takes the LEAN mean normal (gbuffer.frag with
// GBUFFER_LEAN) set this, and the normal here comes from the same map.
layout(binding = DERMIS_UNIT_TS_LEAN_MAP) uniform sampler2D uLeanMap;  // (B.x, B.y, M.xx, M.yy), tangent space
layout(location = DERMIS_LOCATION_TS_LEAN_NORMALS) uniform int uLeanNormals;
layout(location = DERMIS_LOCATION_TS_BURIED_EMPTY) uniform int uBuriedEmpty;

in vec3 vWorldPositionM;
in vec3 vWorldNormal;
in vec4 vWorldTangent;
in vec2 vMapUv;
in vec3 vColour;
in vec4 vEnvironment;
in vec3 vDPduM;  // metres per unit of the mesh's UV
in vec3 vDPdvM;
in float vBuried;  // 1 inside the body (mesh/UvLayout.h)

layout(location = 0) out vec4 oIrradiance;

// The SSAO of the pixel that shows this point, or 1 where no pixel does.
float ambientOcclusion(vec3 worldPositionM) {
    ivec2 aoSize = textureSize(uAmbientOcclusion, 0);
    if (aoSize == ivec2(1)) return texelFetch(uAmbientOcclusion, ivec2(0), 0).r;
    vec4 clip = uFrame.clipFromWorld * vec4(worldPositionM, 1.0);
    if (clip.w <= kTiny) return 1.0;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThanEqual(abs(ndc), vec2(1.0)))) return 1.0;
    ivec2 pixel = clamp(ivec2((ndc * 0.5 + 0.5) * uFrame.viewportPx), ivec2(0), ivec2(uFrame.viewportPx) - 1);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    if (isBackgroundKey(key)) return 1.0;
    float viewDepthM = -(uFrame.viewFromWorld * vec4(worldPositionM, 1.0)).z;
    float toleranceM = max(0.002, 0.01 * viewDepthM);
    return abs(viewDepthFromKey(key) - viewDepthM) < toleranceM ? texelFetch(uAmbientOcclusion, pixel, 0).r : 1.0;
}

// The footprint of the screen pixel at this point in map UV: the inverse of
// the Jacobian of pixel coordinates by UV, J = d(pixel)/d(P) x d(P)/d(uv),
// d(pixel)/d(P) from the camera's projection at the point. Where J is singular
// (the point behind the camera, or the surface edge-on to the eye: no pixel
// shows it) the texel's own gradients stand.
MapFootprint cameraFootprint(vec2 texelDx, vec2 texelDy) {
    mat4 C = uFrame.clipFromWorld;
    vec4 clip = C * vec4(vWorldPositionM, 1.0);
    if (clip.w > kTiny) {
        vec3 rowX = vec3(C[0][0], C[1][0], C[2][0]);
        vec3 rowY = vec3(C[0][1], C[1][1], C[2][1]);
        vec3 rowW = vec3(C[0][3], C[1][3], C[2][3]);
        float perW2 = 0.5 / (clip.w * clip.w);
        vec3 pixelXPerM = (rowX * clip.w - clip.x * rowW) * (perW2 * uFrame.viewportPx.x);
        vec3 pixelYPerM = (rowY * clip.w - clip.y * rowW) * (perW2 * uFrame.viewportPx.y);
        mat2 pixelPerUv = mat2(dot(pixelXPerM, vDPduM), dot(pixelYPerM, vDPduM), dot(pixelXPerM, vDPdvM),
                               dot(pixelYPerM, vDPdvM));
        if (abs(determinant(pixelPerUv)) > 1e-12) {
            mat2 uvPerPixel = inverse(pixelPerUv);
            // The maps' v runs the other way when the material flips it.
            vec2 flip = vec2(1.0, uObject.flipV > 0.5 ? -1.0 : 1.0);
            float scale = exp2(uFrame.materialMipBias);
            return projectedFootprint(vMapUv, uvPerPixel[0] * flip * scale, uvPerPixel[1] * flip * scale);
        }
    }
    return projectedFootprint(vMapUv, texelDx, texelDy);
}

void main() {
    // Surface inside the body takes no light and gives none: an empty texel,
    // which the blurs leave out, as the reference leaves it out as a donor.
    // The capture for the reference keeps its light (IrradianceCapture.h): a
    // donor beside the junction reads texels within reach, and an empty one
    // would count as no light there.
    if (uBuriedEmpty != 0 && vBuried > 0.5) {
        oIrradiance = vec4(0.0);
        return;
    }
    MapFootprint at = cameraFootprint(dFdx(vMapUv), dFdy(vMapUv));
    vec3 geometricN = safeNormalize(vWorldNormal, vec3(0.0, 1.0, 0.0));
    vec3 N = geometricN;
    if (uObject.hasNormalMap > 0.5) {
        vec3 T = vWorldTangent.xyz - N * dot(N, vWorldTangent.xyz);
        T = safeNormalize(T, abs(N.x) < 0.9 ? normalize(cross(N, vec3(1, 0, 0))) : normalize(cross(N, vec3(0, 1, 0))));
        vec3 B = cross(N, T) * (vWorldTangent.w < 0.0 ? -1.0 : 1.0);
        mat3 TBN = mat3(T, B, N);
        if (uLeanNormals != 0) {
            N = safeNormalize(leanMeanNormal(readMap(uLeanMap, at).xy, TBN), N);
        } else {
            N = safeNormalize(TBN * (readMap(uNormalMap, at).xyz * 2.0 - 1.0), N);
        }
    }
    vec3 albedo = materialAlbedo(uAlbedoMap, at, vColour);
    float roughness = materialRoughness(at);
    float rhoS = materialRhoS(at);
    bool conserveEnergy = uFrame.energyConservation != 0;

    float occlusion = ambientOcclusion(vWorldPositionM);
    vec3 irradiance = uFrame.ambient.rgb * occlusion;
    if (environmentLit()) {
        int mode = environmentOcclusion();
        vec3 environment = mode == DERMIS_ENV_OCCLUSION_TRANSFER ? transferredIrradiance(vEnvironment, N) : environmentIrradiance(N);
        if (mode == DERMIS_ENV_OCCLUSION_SSAO) environment *= occlusion;
        irradiance += environment * (conserveEnergy ? environmentDiffuseShare(N, roughness, rhoS) : vec3(1.0));
    }
    int lightCount = uFrame.lightCount;
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        vec3 radiance = incidentRadiance(light, vWorldPositionM, L);
        float nDotL = dot(N, L);
        if (nDotL <= 0.0) continue;
        int slot = int(light.shadowSlot);
        float visibility = 1.0;
        if (slot >= 0) visibility = shadowVisibility(uShadowMaps[slot], light, vWorldPositionM, N, gl_FragCoord.xy);
        float diffuseShare = conserveEnergy ? energyLeftForDiffuse(uEnergy, nDotL, roughness, rhoS) : 1.0;
        irradiance += radiance * (nDotL * visibility * diffuseShare);
    }

    float alpha = 1.0;
    if (uTs.hasTsm > 0.5) alpha = encodeThickness(tsmThicknessMm(uTsm, vWorldPositionM, geometricN));
    oIrradiance = vec4(sanitizeColour(irradiance * albedoPower(albedo, uFrame.mixRatio)), alpha);
}
