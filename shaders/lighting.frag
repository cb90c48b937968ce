// Deferred lighting (docs/screen-space.md, step 4) into two targets:
//   0: diffuse irradiance times the pre-scatter albedo^mix (Chappuis 2011 §2.2.4),
//      the input of the SSS blur. Its alpha is 1, or with LIGHTING_LEAN the
//      G-buffer's LEAN cross moment M'.xy, which the blur carries along with
//      the irradiance (include/SssChain.glsl, include/Lean.glsl). Each light's share is scaled by the energy
//      the specular lobe leaves, 1 - rho_s rho_dt(N.L, m) (Chappuis 2011 §2.6);
//      the uniform ambient by the SSAO; the environment's diffuse light
//      (include/Environment.glsl) by the occlusion the scene chose: none, the
//      SSAO, or the per-vertex transfer (the G-buffer's environment target),
//      so that no light is darkened twice (docs/environment.md, "Occlusion").
//   1: specular (Kelemen/Szirmay-Kalos) of the lights and the environment,
//      kept apart and added after the blur; with LIGHTING_LEAN, for
//      characters with LEAN maps (their lobe comes from
//      include/LeanLights.glsl), alpha 0 and in red the environment's
//      specular occlusion.
//   Where a pixel's profile slot uses a technique that scatters in this pass
//   (the pre-integrated one), each light's N.L is that technique's falloff and
//   its shadow the one the profile scatters (engine/render/LightingScatter.h);
//   that code is compiled only with LIGHTING_SCATTER 1, which the pass draws
//   over the rectangles of the slots that scatter here, after drawing the
//   frame without it (a CPU driver would run it under a mask for every pixel).
//   2: the shadow visibility of each shadowed light, channel = its shadow
//      slot (0 where N.L <= 0), for the LEAN specular pass after the blur,
//      which would otherwise filter every shadow map again. Bound only in the
//      LEAN variants (passes/LightingPass.h); unbound, the write is dropped.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Shadows.glsl"
#include "Specular.glsl"
#include "Lights.glsl"
#include "EnergyConservation.glsl"
#include "Environment.glsl"
#include "LightingTechniques.glsl"  // generated from the SSS technique registry

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform sampler2D uAmbientOcclusion;
layout(binding = 4) uniform sampler2D uShadowMaps[DERMIS_MAX_SHADOWED_LIGHTS];
layout(binding = DERMIS_UNIT_BECKMANN) uniform sampler2D uBeckmann;
layout(binding = DERMIS_UNIT_ENERGY) uniform sampler2D uEnergy;
#ifdef LIGHTING_LEAN
layout(binding = 8) uniform sampler2D uLeanCross;  // R16F M'.xy
#endif
layout(binding = 9) uniform sampler2D uEnvironmentTransfer;  // the G-buffer's environment target (occlusion "transfer")

in vec2 vUv;
layout(location = 0) out vec4 oIrradiance;
layout(location = 1) out vec4 oSpecular;
layout(location = 2) out vec4 oVisibility;

#if DERMIS_MAX_SHADOWED_LIGHTS > 4
#error "oVisibility holds one shadowed light per channel: at most 4"
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // From the pixel, not the interpolated vUv: the pass draws the characters'
    // rectangles (passes/FullscreenPass.h), whose interpolation rounds otherwise.
    vec2 uv = gl_FragCoord.xy * uFrame.pixelSizeUv;
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (depth >= 1.0) {
        oIrradiance = vec4(0.0);
        oSpecular = vec4(0.0);
        oVisibility = vec4(0.0);
        return;
    }
    vec4 albedoId = texelFetch(uAlbedo, pixel, 0);
    vec3 albedo = albedoId.rgb;
#ifdef LIGHTING_LEAN
    // Characters with LEAN maps take their specular from the LEAN lobe later.
    int objectId = clamp(int(albedoId.a * 255.0 + 0.5), 0, DERMIS_MAX_CHARACTERS);
    bool keepSpecular = uCharacters.characters[objectId].hasLeanMaps < 0.5;
#else
    const bool keepSpecular = true;
#endif
    vec4 normalMaterial = texelFetch(uNormalMaterial, pixel, 0);
    float roughness = normalMaterial.z;
    float rhoS = normalMaterial.w;
    bool conserveEnergy = uFrame.energyConservation != 0;

    vec3 viewPositionM = viewPositionFromDepth(uv, depth, uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 N = safeNormalize(mat3(uFrame.worldFromView) * decodeNormal(normalMaterial.xy), vec3(0.0, 1.0, 0.0));
    vec3 V = safeNormalize(uFrame.cameraPositionM.xyz - worldPositionM, N);

    float ambientOcclusion = texture(uAmbientOcclusion, uv).r;
    vec3 irradiance = uFrame.ambient.rgb * ambientOcclusion;
    vec3 specular = vec3(0.0);
    float environmentVisibility = 1.0;
    if (environmentLit()) {
        int occlusion = environmentOcclusion();
        vec4 environment;
        if (occlusion == DERMIS_ENV_OCCLUSION_TRANSFER) {
            environment = texelFetch(uEnvironmentTransfer, pixel, 0);
            environment.rgb = transferredIrradiance(environment, N);
        } else {
            environment = vec4(environmentIrradiance(N), occlusion == DERMIS_ENV_OCCLUSION_SSAO ? ambientOcclusion : 1.0);
        }
        if (occlusion == DERMIS_ENV_OCCLUSION_SSAO) environment.rgb *= ambientOcclusion;
        irradiance += environment.rgb * (conserveEnergy ? environmentDiffuseShare(N, roughness, rhoS) : vec3(1.0));
        environmentVisibility = specularOcclusion(clamp(dot(N, V), 0.0, 1.0), environment.a, roughness);
        if (keepSpecular) specular += environmentSpecular(uEnergy, N, V, roughness, rhoS) * environmentVisibility;
    }
    // s.technique != 0: the pixel's technique scatters in this pass.
#if LIGHTING_SCATTER
    LightingScatterSurface s = lightingScatterSurface(pixel);
#else
    const LightingScatterSurface s = LightingScatterSurface(0, 0, 0.0, 0.0);  // no slot of the frame scatters here
#endif
    bool scatterShadows = s.technique != 0 && lightingScatterShadowShows(s, -viewPositionM.z);
    vec4 shadowed = vec4(0.0);
    int lightCount = uFrame.lightCount;
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        float nDotL = dot(N, L);
        // Scattered light wraps past the terminator (where the falloff is > 0).
        if (nDotL <= 0.0 && s.technique == 0) continue;
        int slot = int(light.shadowSlot);
        float visibility = 1.0;
        vec3 diffuseVisibility = vec3(1.0);  // where the technique scatters here: the shadow the profile scatters
        if (slot >= 0) {
            if (scatterShadows) {
                vec4 scattered = lightingScatterShadow(s, uShadowMaps[slot], light, worldPositionM, N, nDotL);
                diffuseVisibility = scattered.rgb;
                visibility = scattered.a;
            } else {
                visibility = shadowVisibility(uShadowMaps[slot], light, worldPositionM, N, gl_FragCoord.xy);
                diffuseVisibility = vec3(visibility);
            }
            if (nDotL > 0.0) shadowed[slot] = visibility;
        }
        float diffuseShare = conserveEnergy ? energyLeftForDiffuse(uEnergy, max(nDotL, 0.0), roughness, rhoS) : 1.0;
        vec3 falloff = s.technique != 0 ? lightingScatterFalloff(s, nDotL) : vec3(nDotL);
        irradiance += radiance * (falloff * diffuseVisibility * diffuseShare);
        if (nDotL <= 0.0) continue;
        if (keepSpecular) specular += radiance * (visibility * ksSpecular(uBeckmann, N, L, V, roughness, rhoS));
    }

    float mixRatio = uFrame.mixRatio;
#ifdef LIGHTING_LEAN
    float alpha = texelFetch(uLeanCross, ivec2(gl_FragCoord.xy), 0).r;
#else
    float alpha = 1.0;
#endif
    oIrradiance = vec4(sanitizeColour(irradiance * albedoPower(albedo, mixRatio)), alpha);
    // Alpha 0 marks a pixel whose specular the LEAN lobe gives (LeanLights.glsl).
    oSpecular = keepSpecular ? vec4(sanitizeColour(specular), 1.0) : vec4(environmentVisibility, 0.0, 0.0, 0.0);
    oVisibility = shadowed;
}
