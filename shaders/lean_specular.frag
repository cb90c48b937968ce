// The specular of the LEAN variants as its own pass (include/LeanLights.glsl),
// for the specular AOV; the final image computes the same in composite.frag.
// Linear HDR out.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "EnergyConservation.glsl"
layout(binding = DERMIS_UNIT_ENERGY) uniform sampler2D uEnergy;
#include "LeanLights.glsl"

layout(binding = 0) uniform sampler2D uDepth;
layout(binding = 1) uniform sampler2D uAlbedo;
layout(binding = 2) uniform sampler2D uNormalMaterial;
layout(binding = 3) uniform sampler2D uLeanMoments;  // blurred (B'.x, B'.y, M'.xx, M'.yy)
layout(binding = 4) uniform sampler2D uAccumulated;  // SSS-accumulated irradiance, a = blurred M'.xy
layout(binding = 5) uniform sampler2D uVisibility;   // per shadow slot
layout(binding = 6) uniform sampler2D uSpecular;     // the lighting pass's KS specular

in vec2 vUv;
layout(location = 0) out vec4 oSpecular;

void shade() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(uDepth, pixel, 0).r;
    if (depth >= 1.0) {
        oSpecular = vec4(0.0);
        return;
    }
    oSpecular = vec4(leanPixelSpecular(pixel, vUv, depth, texelFetch(uSpecular, pixel, 0),
                                       texelFetch(uAccumulated, pixel, 0).a, texelFetch(uNormalMaterial, pixel, 0).w,
                                       uLeanMoments, uVisibility),
                     1.0);
}

// The pass's output goes through the planted NaN of docs/stress.md.
void main() {
    shade();
    oSpecular = debugPlant(oSpecular);
}
