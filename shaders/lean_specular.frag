// LEAN specular after the SSS blur (variants lcb and lbb; DESIGN.md pass 6).
// For pixels of characters with LEAN maps (uCharacters params.w), the sum
// over lights of radiance x shadow visibility x the LEAN lobe of the blurred
// view-plane moments (include/Lean.glsl: the space, the lobe, the clamp);
// other pixels keep the lighting pass's Kelemen/Szirmay-Kalos specular. The
// shadow visibility is the lighting pass's (its target 2), so no shadow map
// is filtered twice. Linear HDR out, replacing the specular the composite adds.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "Specular.glsl"
#include "Lights.glsl"
#include "Lean.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;          // a = object id / 255
layout(binding = 2) uniform sampler2D uNormalMaterial;  // w = rho_s
layout(binding = 3) uniform sampler2D uLeanMoments;     // blurred (B'.x, B'.y, M'.xx, M'.yy)
layout(binding = 4) uniform sampler2D uLeanCross;       // blurred M'.xy
layout(binding = 5) uniform sampler2D uVisibility;      // per shadow slot
layout(binding = 6) uniform sampler2D uSpecular;        // the lighting pass's KS specular

in vec2 vUv;
layout(location = 0) out vec4 oSpecular;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (depth >= 1.0) {
        oSpecular = vec4(0.0);
        return;
    }
    int objectId = clamp(int(texelFetch(uAlbedo, pixel, 0).a * 255.0 + 0.5), 0, DERMIS_MAX_CHARACTERS);
    if (uCharacters.characters[objectId].params.w < 0.5) {
        oSpecular = texelFetch(uSpecular, pixel, 0);
        return;
    }
    vec3 viewPositionM = viewPositionFromDepth(vUv, depth, uFrame.viewFromClip);
    vec3 worldPositionM = (uFrame.worldFromView * vec4(viewPositionM, 1.0)).xyz;
    vec3 V = safeNormalize(-viewPositionM, vec3(0.0, 0.0, 1.0));
    vec4 moments = texelFetch(uLeanMoments, pixel, 0);
    vec3 secondMoments = vec3(moments.zw, texelFetch(uLeanCross, pixel, 0).r);
    float rhoS = texelFetch(uNormalMaterial, pixel, 0).w;
    vec4 visibility = texelFetch(uVisibility, pixel, 0);
    mat3 viewFromWorld = mat3(uFrame.viewFromWorld);

    vec3 specular = vec3(0.0);
    int lightCount = int(uFrame.shading.z);
    for (int i = 0; i < lightCount; ++i) {
        GpuLight light = uLights.lights[i];
        vec3 L;
        vec3 radiance = incidentRadiance(light, worldPositionM, L);
        int slot = int(light.directionShadow.w);
        float lit = slot >= 0 ? visibility[slot] : 1.0;
        if (lit <= 0.0) continue;
        specular += radiance * (lit * leanSpecular(moments.xy, secondMoments, viewFromWorld * L, V, rhoS));
    }
    oSpecular = vec4(sanitizeColour(specular), 1.0);
}
