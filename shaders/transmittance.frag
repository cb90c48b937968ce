// Adds the light every shadowed back light carries through thin regions
// (include/Transmittance.glsl) into the diffuse light, for SSS pixels only
// (the stencil test keeps the rest). Output is blended additively.
// With the thickness AOV it writes, instead, the thickness in mm along the
// first back light's ray (0 where there is none, or where the point is the
// surface nearest that light): a check of thicknessMm. Positions come
// from the depth key: the depth buffer is attached for the stencil test, so
// sampling it would be a feedback loop.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"
#include "Lights.glsl"
#include "Transmittance.glsl"

layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform usampler2D uDepthKey;
layout(binding = 4) uniform sampler2D uShadowMaps[DERMIS_MAX_SHADOWED_LIGHTS];
layout(binding = DERMIS_UNIT_SCATTER) uniform sampler2D uScatter;  // G-buffer: s, the file's thickness in mm

in vec2 vUv;
layout(location = 0) out vec4 oTransmitted;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    int slot = slotFromKey(key);
    if (slot <= 0 || slot > DERMIS_MAX_PROFILES) {
        oTransmitted = vec4(0.0);
        return;
    }
    vec2 scatter = texelFetch(uScatter, pixel, 0).rg;
    if (scatter.r <= 0.0) {  // a surface that does not scatter does not glow (docs/materials.md)
        oTransmitted = vec4(0.0);
        return;
    }
    vec3 albedo = texelFetch(uAlbedo, pixel, 0).rgb;
    vec3 viewPositionM = viewPositionFromViewDepth(vUv, viewDepthFromKey(key), uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 N = safeNormalize(mat3(uFrame.worldFromView) * decodeNormal(texelFetch(uNormalMaterial, pixel, 0).xy),
                           vec3(0.0, 1.0, 0.0));
    float shrinkMm = uProfiles.transmittanceShrinkMm;
    float pixelsPerMm = uFrame.pixelsPerMetreAtUnitDepth / max(viewDepthFromKey(key), kTiny) * 1e-3;

    bool writeThickness = uFrame.aov == DERMIS_AOV_THICKNESS;
    vec3 transmitted = vec3(0.0);
    int lightCount = uFrame.lightCount;
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        int shadowSlot = int(light.shadowSlot);
        if (shadowSlot < 0 || light.backLight < 0.5) continue;  // needs a map, and to be behind
        vec3 L;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        float sMm = thicknessMm(uShadowMaps[shadowSlot], light, worldPositionM, N, shrinkMm);
        if (writeThickness) {
            oTransmitted = vec4(vec3(max(sMm, 0.0)), 0.0);
            return;
        }
        if (sMm < 0.0) continue;
        ProfileParams profile = uProfiles.profiles[slot];
        if (scatter.g > 0.0) {  // KHR_materials_volume: a slab of the file's thickness, where the light is behind
            transmitted += radiance * profileTransmittance(profile, scatter.g) * backLightFactor(N, L);
        } else {
            transmitted += radiance * thinRegionTransmittance(uShadowMaps[shadowSlot], light, profile, worldPositionM, N, L,
                                                              sMm, pixelsPerMm);
        }
    }
    float mixRatio = uFrame.mixRatio;
    oTransmitted = vec4(sanitizeColour(transmitted * scatter.r * uProfiles.transmittanceStrength * albedoPower(albedo, mixRatio)),
                        0.0);
}
