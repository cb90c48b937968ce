// Starts the SSS accumulation: SSS pixels take their profile's identity
// weight (Gaussian 0, plus any Gaussian too narrow to blur this frame, see
// engine/render/SssPlan.h) times the irradiance; every other pixel keeps its
// irradiance unchanged. With SSS_EXTRA_TARGETS > 0 (the LEAN moments, units
// 2.., outputs 1..) the extra targets start the same way with the mean of
// the identity weight (include/SssBlur.glsl says why the mean).
#include "Common.glsl"
#include "UniformBlocks.glsl"

#ifndef SSS_EXTRA_TARGETS
#define SSS_EXTRA_TARGETS 0
#endif
#if SSS_EXTRA_TARGETS < 0 || SSS_EXTRA_TARGETS > 3
#error "SSS_EXTRA_TARGETS must be 0..3"
#endif

layout(binding = 0) uniform sampler2D uIrradiance;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oAccumulated;
#if SSS_EXTRA_TARGETS > 0
layout(binding = 2) uniform sampler2D uExtra[SSS_EXTRA_TARGETS];
layout(location = 1) out vec4 oExtraAccumulated[SSS_EXTRA_TARGETS];
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 irradiance = texelFetch(uIrradiance, pixel, 0);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    int slot = slotFromKey(key);
    vec3 weight = slot > 0 && slot <= DERMIS_MAX_PROFILES ? uProfiles.profiles[slot].info.yzw : vec3(1.0);
    oAccumulated = vec4(irradiance.rgb * weight, irradiance.a);
#if SSS_EXTRA_TARGETS > 0
    float scalarWeight = (weight.r + weight.g + weight.b) / 3.0;
    for (int k = 0; k < SSS_EXTRA_TARGETS; ++k) oExtraAccumulated[k] = scalarWeight * texelFetch(uExtra[k], pixel, 0);
#endif
}
