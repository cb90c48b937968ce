// Starts the SSS accumulation: SSS pixels take their profile's identity
// weight (Gaussian 0, plus any Gaussian too narrow to blur this frame, see
// engine/plan/SssPlan.h) times the irradiance; every other pixel keeps its
// irradiance unchanged. The irradiance's alpha (1, or the LEAN cross moment)
// and, with SSS_EXTRA_TARGETS = 1, the extra target (the LEAN moments, unit
// 2, output 1) start the same way with the mean of the identity weight
// (include/SssChain.glsl says why the mean); output 2 then starts the packed
// chain the blurs read.
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "SssChain.glsl"

layout(binding = 0) uniform sampler2D uIrradiance;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oAccumulated;
#if SSS_EXTRA_TARGETS > 0
layout(binding = 2) uniform sampler2D uExtra;
layout(location = 1) out vec4 oExtraAccumulated;
layout(location = 2) out uvec4 oChain;
#endif

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    vec4 irradiance = texelFetch(uIrradiance, pixel, 0);
    uint key = texelFetch(uDepthKey, pixel, 0).r;
    int slot = slotFromKey(key);
    vec3 weight = slot > 0 && slot <= DERMIS_MAX_PROFILES ? uProfiles.profiles[slot].initWeight : vec3(1.0);
    float scalarWeight = (weight.r + weight.g + weight.b) / 3.0;
    // debugPlant: `dermis stress --plant-nan "sss init"` (the irradiance was sanitised by the lighting pass).
    oAccumulated = debugPlant(vec4(irradiance.rgb * weight, irradiance.a * scalarWeight));
#if SSS_EXTRA_TARGETS > 0
    vec4 extra = texelFetch(uExtra, pixel, 0);
    oExtraAccumulated = scalarWeight * extra;
    oChain = sssPack(vec4(sanitizeColour(irradiance.rgb), sssSanitizeSigned(irradiance).a), sssSanitizeSigned(extra));
#endif
}
