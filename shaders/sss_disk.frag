// The disk technique: one slot's screen-space SSS in one pass; see
// include/DiskSss.glsl for the method, how it is driven and the outputs.
// With SSS_EXTRA_TARGETS = 1 the LEAN moments ride along in the packed chain.
#define DERMIS_USE_DISK_SSS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "DiskSss.glsl"

layout(binding = 0) uniform SSS_CHAIN_SAMPLER uChain;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oAccumulated;  // overwritten on this slot's pixels (no blending)
#if SSS_EXTRA_TARGETS > 0
layout(location = 1) out vec4 oExtraAccumulated;
#endif

void main() {
    SssValues diffused = diskSss(uChain, uDepthKey, ivec2(gl_FragCoord.xy));
    oAccumulated = vec4(sanitizeColour(diffused.v[0].rgb), sssSanitizeSigned(diffused.v[0]).a);  // a: 1 or M'.xy
#if SSS_EXTRA_TARGETS > 0
    oExtraAccumulated = sssSanitizeSigned(diffused.v[1]);
#endif
}
