// LeanLights.glsl: one pixel's specular in the LEAN variants, shared by
// lean_specular.frag (the pass behind the specular AOV) and composite.frag
// (COMPOSITE_LEAN, the final image), so both compute the same thing.
//
// Pixels of characters with LEAN maps (uCharacters params.w) sum over the
// frame's lights: radiance x the lighting pass's shadow visibility (its
// target 2, channel = shadow slot, so no shadow map is filtered twice) x the
// LEAN lobe of the blurred view-plane moments (include/Lean.glsl). Other
// pixels keep the lighting pass's Kelemen/Szirmay-Kalos specular.
//
// Inputs: the G-buffer's depth (in [0,1]), albedo (a = object id / 255) and
// normal+material (w = rho_s); the blurred LEAN moments (B'.x, B'.y, M'.xx,
// M'.yy); the SSS-accumulated irradiance, whose alpha is the blurred M'.xy;
// the visibility; the lighting pass's specular. Needs Common.glsl and
// UniformBlocks.glsl first; `uv` is the pixel centre in [0,1]^2.
#ifndef DERMIS_LEAN_LIGHTS_GLSL
#define DERMIS_LEAN_LIGHTS_GLSL

#include "Lights.glsl"
#include "Lean.glsl"

vec3 leanPixelSpecular(ivec2 pixel, vec2 uv, float depth, sampler2D albedo, sampler2D normalMaterial,
                       sampler2D moments, sampler2D accumulated, sampler2D visibility, sampler2D lightingSpecular) {
    int objectId = clamp(int(texelFetch(albedo, pixel, 0).a * 255.0 + 0.5), 0, DERMIS_MAX_CHARACTERS);
    if (uCharacters.characters[objectId].params.w < 0.5) return texelFetch(lightingSpecular, pixel, 0).rgb;

    vec3 viewPositionM = viewPositionFromDepth(uv, depth, uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 V = safeNormalize(-viewPositionM, vec3(0.0, 0.0, 1.0));
    vec4 m = texelFetch(moments, pixel, 0);
    LeanLobe lobe = leanLobe(m.xy, vec3(m.zw, texelFetch(accumulated, pixel, 0).a), V);
    float rhoS = texelFetch(normalMaterial, pixel, 0).w;
    vec4 lit = texelFetch(visibility, pixel, 0);
    mat3 viewFromWorld = mat3(uFrame.viewFromWorld);

    vec3 specular = vec3(0.0);
    int lightCount = int(uFrame.shading.z);
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        int slot = int(light.directionShadow.w);
        float shadow = slot >= 0 ? lit[slot] : 1.0;
        if (shadow <= 0.0) continue;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        if (max(radiance.r, max(radiance.g, radiance.b)) <= 0.0) continue;
        specular += radiance * (shadow * leanSpecular(lobe, viewFromWorld * L, rhoS));
    }
    return sanitizeColour(specular);
}

#endif
