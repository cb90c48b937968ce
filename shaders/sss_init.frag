// Starts the SSS accumulation: SSS pixels take their profile's identity
// weight (Gaussian 0, plus any Gaussian too narrow to blur this frame, see
// engine/render/SssPlan.h) times the irradiance; every other pixel keeps its
// irradiance unchanged.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uIrradiance;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oAccumulated;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 irradiance = texelFetch(uIrradiance, pixel, 0);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    int slot = slotFromKey(key);
    vec3 weight = slot > 0 && slot <= DERMIS_MAX_PROFILES ? uProfiles.profiles[slot].info.yzw : vec3(1.0);
    oAccumulated = vec4(irradiance.rgb * weight, irradiance.a);
}
