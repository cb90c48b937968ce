// Texture-space step 5, the gather (Chappuis 2011 §2.8 listing 2.11; manual in
// include/TextureSpace.glsl). For this surface's pixels (depth equal to the
// G-buffer's, the same object id and the same profile slot) it writes, into the SSS accumulation the
// composite reads,
//   sum_i w_i T_i(uv) / sum_i w_i  +  the TSM terms,
// where T_i is blurred texture i (the lighting pass's irradiance at this pixel
// for a Gaussian narrower than a texel), replaced by T_0 (the narrowest,
// "local" light) as a chart border comes nearer than seam_blend standard
// deviations of Gaussian i. Its mass beyond the border takes the light across it
// (below). Like the screen-space accumulation this still carries
// albedo^mix; the composite applies albedo^(1-mix), the outgoing energy
// factor and the specular.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "TextureSpace.glsl"
#include "ThinEdges.glsl"

layout(binding = 0) uniform sampler2D uBlurred[DERMIS_MAX_PROFILE_GAUSSIANS];
layout(binding = 8) uniform sampler2D uTsm;
layout(binding = 9) uniform sampler2D uAlbedo;  // G-buffer target 0: a = object id / 255
layout(binding = 10) uniform usampler2D uDepthKey;  // G-buffer target 2: the view depth of the surface kept
layout(binding = DERMIS_UNIT_TS_PIXEL_IRRADIANCE) uniform sampler2D uPixelIrradiance;  // the lighting pass's irradiance, the same light at this pixel
layout(binding = DERMIS_UNIT_HIDDEN_SIDE) uniform sampler2D uHiddenSide;  // passes/ThinEdgePasses.cpp

in vec3 vWorldPositionM;
in vec2 vUv;
in vec3 vDPduM;
in vec3 vDPdvM;
in float vBorderDistanceM;
in vec4 vSeamContinuation;
flat in vec4 vProvokingUvs;

layout(location = 0) out vec4 oDiffuse;

// The G-buffer and this pass interpolate the same triangle at the same pixel
// centre: their view depths differ by float rounding (under a micrometre at
// 1 m) and the key's 1 um step. A surface further behind is hidden: the depth
// test's slope-scaled margin let it through at a grazing angle, and it would
// overwrite the visible one with the light of another part of the layout.
const float kSameSurfaceMm = 0.1;
const float kSameSurfacePerDepth = 1e-4;

// A Gaussian narrower than a texel is not resolved by the irradiance
// texture: its texels sample the light up to 0.7 texel away from this point
// and the bilinear read blurs by up to 1/4 texel^2, so at a shadow edge a
// pixel reads the shadow of the texel beside it (the head scan at 256^2,
// texels 2.6 x 1.2 mm there: an eyelid pixel with irradiance 0.74, RGB sum,
// read 0.09 from the texture and showed a diffuse of 0.105 where 512^2 and
// 1024^2 show 0.36). For those Gaussians the lighting pass's irradiance at
// this pixel, the same light (ts_irradiance.frag) at this very point, stands
// in; from 0.5 to 1 texel (the coarser of u and v, or the pixel's footprint
// where that is coarser) it gives way to the texture.
//
// The pixel resolves no more than the texel does: where a texel is smaller
// than the pixel's footprint, a Gaussian narrower than the footprint keeps
// the texels' detail (the normal map's bumps, lit) that the pixel cannot
// show, and the bilinear read at the pixel's centre picks one texel's worth
// of it: speckle. The same rule then measures the Gaussian against the
// footprint, where the lighting pass's irradiance is the light of the
// footprint's filtered normal, as in screen space. Against the matched
// reference at 640x360 (docs/texture-space.md, "Gaussians under a pixel"):
// with the texture at 2048^2 instead of the default's choice, the default
// head 1.41% -> 1.33% and the scan 1.51% -> 1.19%; at the default size
// 1.364% -> 1.345% and 1.145% -> 1.140% (the matched change at spp 16).
const float kUnresolvedTexels = 0.5;
const float kResolvedTexels = 1.0;

// The agreement test of the seam continuation below: how much larger the
// chart beyond may be drawn than this one, and a slack for rounding.
const float kSeamScaleRatio = 4.0;
const float kSeamSlackTexels = 2.0;

void main() {
    int objectId = int(texelFetch(uAlbedo, ivec2(gl_FragCoord.xy), 0).a * 255.0 + 0.5);
    if (objectId != int(uObject.objectId + 0.5)) discard;
    float viewDepthM = -(uFrame.viewFromWorld * vec4(vWorldPositionM, 1.0)).z;
    uint key = texelFetch(uDepthKey, ivec2(gl_FragCoord.xy), 0).r;
    // Another surface of this character (another profile, or opaque) kept the pixel.
    if (slotFromKey(key) != int(uObject.profileSlot + 0.5)) discard;
    float keptDepthM = viewDepthFromKey(key);
    if (abs(viewDepthM - keptDepthM) > max(kSameSurfaceMm * 1e-3, kSameSurfacePerDepth * keptDepthM)) discard;
    // A triangle seen from behind (a sliver at a silhouette, a fold of the
    // mesh): its texels were lit with the normal facing away, while the
    // G-buffer turned it towards the viewer. The pixel keeps the lighting
    // pass's irradiance instead, which the accumulation started from.
    if (!gl_FrontFacing) discard;

    int count = int(uTs.gaussianCount);
    float borderMm = vBorderDistanceM * 1000.0;
    float seamBlend = uTs.seamBlendStdDevs;
    vec3 local = texture(uBlurred[0], vUv).rgb;
    vec3 pixelIrradiance = texelFetch(uPixelIrradiance, ivec2(gl_FragCoord.xy), 0).rgb;
    float mmPerTexel = max(length(vDPduM), length(vDPdvM)) * 1000.0 * uTs.texelUv;
    float mmPerPixel = viewDepthM / uFrame.pixelsPerMetreAtUnitDepth * 1000.0;
    float mmResolved = max(mmPerTexel, mmPerPixel);
    // A Gaussian's mass beyond the nearest chart border (its 1-D tail there)
    // takes the light across the border in place of the local light:
    // - at a seam, the blurred texture's light at the border point on the
    //   chart beyond (mesh/UvLayout.h), where the surface goes on flat; where
    //   it turns round (the rim of a thin part: an ear's two faces are charts
    //   of their own that meet at its rim) the thin-edge fill of
    //   include/ThinEdges.glsl with that light as the hidden side's;
    // - at the mesh's own edge, the thin-edge fill from the hidden-side pass,
    //   as a screen-space tap past the outline takes it (the slope test
    //   takes the surface's angle to the view).
    vec3 N = normalize(cross(vDPduM, vDPdvM));
    vec3 V = normalize(uFrame.cameraPositionM.xyz - vWorldPositionM);
    float facing = max(abs(dot(N, V)), kTiny);
    vec4 hiddenSide = hiddenSideAt(uHiddenSide, ivec2(gl_FragCoord.xy));
    float thinWeight = thinEdgeWeight(hiddenSide, sqrt(max(1.0 - facing * facing, 0.0)) / facing);
    vec3 thinFill = thinEdgeFill(local, hiddenSide, thinWeight) - local;
    float atSeam = clamp(vSeamContinuation.z, 0.0, 1.0);
    // The continuation is interpolated over the triangle. Along one seam its
    // vertices' continuations lie as far apart as the vertices themselves,
    // give or take the two charts' scales; a triangle whose vertices are
    // nearest to different seams interpolates between unrelated places of
    // the layout, and takes the mesh-edge fill instead.
    float acrossUv = length(vSeamContinuation.xy - vProvokingUvs.zw);
    float alongUv = length(vUv - vProvokingUvs.xy);
    if (acrossUv > kSeamScaleRatio * alongUv + kSeamSlackTexels * uTs.texelUv) atSeam = 0.0;
    // Where the thin-edge passes do not run (transmittance.thin_edges off),
    // a seam round a rim takes no fill, as a mesh edge does.
    float seamTurn = thinEdgeOpposed(vSeamContinuation.w);
    bool thinEdgesOn = textureSize(uHiddenSide, 0) != ivec2(1);
    vec3 sum = vec3(0.0);
    vec3 weightSum = vec3(0.0);
    vec4 blurred[DERMIS_MAX_PROFILE_GAUSSIANS];
    for (int i = 0; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
        if (i >= count) break;
        blurred[i] = texture(uBlurred[i], vUv);
        float sigmaMm = sqrt(uTs.gaussians[i].a);
        float trust = seamBlend > 0.0 ? smoothstep(0.0, seamBlend * sigmaMm, borderMm) : 1.0;
        float resolved = smoothstep(kUnresolvedTexels, kResolvedTexels, sigmaMm / max(mmResolved, kTiny));
        vec3 light = mix(pixelIrradiance, blurred[i].rgb, resolved);
        float beyondBorder = normalUpperTail(borderMm / max(sigmaMm, kTiny));
        vec3 across = texture(uBlurred[i], vSeamContinuation.xy).rgb;
        vec3 acrossSeam = mix(across - local, thinEdgesOn ? thinEdgeRim(local, across) - local : vec3(0.0), seamTurn);
        vec3 beyond = mix(thinFill, acrossSeam, atSeam);
        sum += uTs.gaussians[i].rgb * (mix(local, light, trust) + beyondBorder * beyond);
        weightSum += uTs.gaussians[i].rgb;
    }
    vec3 diffuse = sum / max(weightSum, vec3(kTiny));

    if (uTs.hasTsm > 0.5) {
        vec4 tap = tsmTap(uTsm, vWorldPositionM);
        if (tap.w > 0.0) {
            // UV distance to the light-facing point A, in mm at this point C.
            float mmPerUv = 0.5 * (length(vDPduM) + length(vDPdvM)) * 1000.0;
            float distanceMm = length(vUv - tap.yz) * mmPerUv;
            int first = max(int(uTs.tsmFirstGaussian), 1);
            for (int i = 1; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
                if (i >= count) break;
                if (i < first) continue;
                float varianceMm2 = max(uTs.gaussians[i].a, 1e-6);
                float dMm = decodeThicknessMm(blurred[i - 1].a);
                float fade = exp(-dMm * dMm / (2.0 * varianceMm2));
                float apart = clamp(distanceMm / (6.0 * sqrt(varianceMm2)), 0.0, 1.0);
                vec3 farSide = texture(uBlurred[i], tap.yz).rgb;
                diffuse += uTs.tsmStrength * uTs.gaussians[i].rgb / max(weightSum, vec3(kTiny)) * (fade * apart) * farSide;
            }
        }
    }
    oDiffuse = vec4(sanitizeColour(diffuse), 1.0);
}
