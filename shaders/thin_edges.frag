// The thin-edge pass (include/ThinEdges.glsl, THE PASS): per SSS pixel, the
// light of the part's hidden side (rgb, times albedo^mix) and the weight of
// the fill (a) from the view ray's path through the part. The stencil keeps
// SSS pixels; the others keep the clear value (0: no fill).
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"
#include "Lights.glsl"
#include "Transmittance.glsl"
#include "Environment.glsl"
#include "ThinEdges.glsl"

layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform usampler2D uDepthKey;
layout(binding = 4) uniform sampler2D uShadowMaps[DERMIS_MAX_SHADOWED_LIGHTS];
layout(binding = 9) uniform sampler2D uBackDepth;    // the back-depth pass: window depth of the nearest back face
layout(binding = 10) uniform sampler2D uBackNormal;  // and its octahedral view normal

in vec2 vUv;
layout(location = 0) out vec4 oHiddenSide;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    int slot = slotFromKey(key);
    float backDepth = texelFetch(uBackDepth, pixel, 0).r;
    if (slot <= 0 || slot > DERMIS_MAX_PROFILES || backDepth >= 1.0) {
        oHiddenSide = vec4(0.0);  // no back face behind the pixel (an open mesh): nothing to fill with
        return;
    }
    float frontDepthM = viewDepthFromKey(key);
    vec3 backViewM = viewPositionFromDepth(vUv, backDepth, uFrame.viewFromClip);
    float pathMm = (-backViewM.z - frontDepthM) * 1000.0;
    vec3 backWorldM = (uFrame.worldFromView * vec4(backViewM, 1.0)).xyz;
    vec3 viewN = decodeNormal(texelFetch(uNormalMaterial, pixel, 0).xy);
    vec3 N = safeNormalize(mat3(uFrame.worldFromView) * viewN, vec3(0.0, 1.0, 0.0));
    float opposed = -dot(viewN, decodeNormal(texelFetch(uBackNormal, pixel, 0).xy));

    // A back face in front of the pixel's surface (another part's, seen through an opening) says nothing.
    float weight = (pathMm > 0.0 ? 1.0 - smoothstep(THIN_EDGE_FULL_MM, THIN_EDGE_NONE_MM, pathMm) : 0.0) *
                   thinEdgeOpposed(opposed);
    // A thick part (most of a head) takes no fill: its hidden side's light is not needed.
    vec3 hidden = vec3(0.0);
    if (weight > 0.0) {
        hidden = uFrame.ambient.rgb;
        if (environmentLit()) hidden += environmentIrradiance(-N);
        int lightCount = uFrame.lightCount;
        for (int i = 0; i < lightCount; ++i) {
            GpuLight light = uLights.lights[i];
            vec3 L;
            vec3 radiance = incidentRadiance(light, backWorldM, L);
            float facing = backLightFactor(N, L);
            if (facing <= 0.0) continue;
            int shadowSlot = int(light.shadowSlot);
            // thicknessMm is -1 where the point is the surface nearest the light: lit.
            bool lit = shadowSlot < 0 || thicknessMm(uShadowMaps[shadowSlot], light, backWorldM, -N, 0.0) < 0.0;
            if (lit) hidden += radiance * facing;
        }
    }
    vec3 albedo = texelFetch(uAlbedo, pixel, 0).rgb;
    oHiddenSide = vec4(sanitizeColour(hidden * albedoPower(albedo, uFrame.mixRatio)), sanitiseRange(weight, 0.0, 1.0, 0.0));
}
