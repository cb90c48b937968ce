// One direction of Separable SSS for one profile slot; see
// include/SeparableSss.glsl for the method, how it is driven and the outputs.
// With SSS_EXTRA_TARGETS = 1 the LEAN moments ride along in the packed chain.
#define DERMIS_USE_SEPARABLE_SSS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "SeparableSss.glsl"

layout(binding = 0) uniform SSS_CHAIN_SAMPLER uChain;
layout(binding = 1) uniform usampler2D uDepthKey;

#if SEPARABLE_SSS_LAST
layout(location = 0) out vec4 oAccumulated;  // replaces sss init's value
#if SSS_EXTRA_TARGETS > 0
layout(location = 1) out vec4 oExtraAccumulated;
#endif
#elif SSS_EXTRA_TARGETS > 0
layout(location = 0) out uvec4 oChain;  // the packed chain: colour and moments
#else
layout(location = 0) out vec4 oChain;
#endif

void main() {
    SssValues blurred = separableSssStep(uChain, uDepthKey, ivec2(gl_FragCoord.xy));
    vec4 colour = vec4(sanitizeColour(blurred.v[0].rgb), sssSanitizeSigned(blurred.v[0]).a);  // a: 1 or M'.xy
#if SSS_EXTRA_TARGETS > 0
    vec4 extra = sssSanitizeSigned(blurred.v[1]);
#endif
#if SEPARABLE_SSS_LAST
    oAccumulated = colour;
#if SSS_EXTRA_TARGETS > 0
    oExtraAccumulated = extra;
#endif
#elif SSS_EXTRA_TARGETS > 0
    oChain = sssPack(colour, extra);
#else
    oChain = colour;
#endif
}
