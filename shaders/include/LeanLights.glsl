// LeanLights.glsl: one pixel's specular in the LEAN variants, shared by
// lean_specular.frag (the pass behind the specular AOV) and composite.frag
// (COMPOSITE_LEAN, the final image), so both compute the same thing.
//
// Pixels of characters with LEAN maps (uCharacters params.w; the lighting
// pass marks them with a specular alpha of 0) sum over the frame's lights: radiance x the lighting pass's shadow visibility (its
// target 2, channel = shadow slot, so no shadow map is filtered twice) x the
// LEAN lobe of the blurred view-plane moments (include/Lean.glsl). Other
// pixels keep the lighting pass's Kelemen/Szirmay-Kalos specular.
//
// Inputs: the pixel's depth (in [0,1]) and centre `uv` in [0,1]^2, the
// lighting pass's specular (alpha 0 marks a LEAN pixel), the blurred M'.xy
// (the SSS-accumulated irradiance's alpha), rho_s (G-buffer normal+material
// .w), and the textures of the blurred LEAN moments (B'.x, B'.y, M'.xx,
// M'.yy) and of the visibility. The caller fetches what it shares with the
// rest of its shader; the two textures are fetched before the branch (on
// llvmpipe a fetch under divergent control flow costs several times more).
// The environment's specular (include/Environment.glsl) goes through the same
// lobe: its mean normal and an isotropic Beckmann width with the lobe's
// slope variance, m^2 = trace(Sigma_m) (Lean.glsl: m^2 / 2 per axis), the
// specular occlusion being what the lighting pass wrote into the LEAN pixel's
// specular (its red channel).
// Needs Common.glsl, UniformBlocks.glsl and EnergyConservation.glsl (with
// uEnergy bound) first.
#ifndef DERMIS_LEAN_LIGHTS_GLSL
#define DERMIS_LEAN_LIGHTS_GLSL

#include "Lights.glsl"
#include "Lean.glsl"
#include "Environment.glsl"

// The environment's specular through a LEAN lobe, view-space V.
vec3 leanEnvironmentSpecular(LeanLobe lobe, vec3 V, float rhoS, float occlusion) {
    if (!environmentLit()) return vec3(0.0);
    vec3 meanNormal = vec3(lobe.meanFromView[0][2], lobe.meanFromView[1][2], lobe.meanFromView[2][2]);
    vec3 Q = lobe.inverseCovariance;
    float determinant = max(Q.x * Q.y - Q.z * Q.z, 1e-20);
    float m = sqrt(max((Q.x + Q.y) / determinant, 0.0));
    mat3 worldFromView = mat3(uFrame.worldFromView);
    return environmentSpecular(uEnergy, worldFromView * meanNormal, worldFromView * V, m, rhoS) * occlusion;
}

vec3 leanPixelSpecular(ivec2 pixel, vec2 uv, float depth, vec4 lightingSpecular, float crossMoment, float rhoS,
                       sampler2D moments, sampler2D visibility) {
    vec4 m = texelFetch(moments, pixel, 0);
    vec4 lit = texelFetch(visibility, pixel, 0);
    if (lightingSpecular.a > 0.5) return lightingSpecular.rgb;

    vec3 viewPositionM = viewPositionFromDepth(uv, depth, uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 V = safeNormalize(-viewPositionM, vec3(0.0, 0.0, 1.0));
    LeanLobe lobe = leanLobe(m.xy, vec3(m.zw, crossMoment), V);
    mat3 viewFromWorld = mat3(uFrame.viewFromWorld);

    vec3 specular = vec3(0.0);
    int lightCount = uFrame.lightCount;
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        int slot = int(light.shadowSlot);
        float shadow = slot >= 0 ? lit[slot] : 1.0;
        if (shadow <= 0.0) continue;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        if (max(radiance.r, max(radiance.g, radiance.b)) <= 0.0) continue;
        specular += radiance * (shadow * leanSpecular(lobe, viewFromWorld * L, rhoS));
    }
    specular += leanEnvironmentSpecular(lobe, V, rhoS, lightingSpecular.r);
    return sanitizeColour(specular);
}

#endif
