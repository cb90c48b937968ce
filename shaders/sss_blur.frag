// One direction of one Gaussian step of the screen-space SSS chain; see
// include/SssBlur.glsl for the method, how it is driven and the outputs.
// With SSS_EXTRA_TARGETS = 1 the LEAN moments ride along in a packed chain.
#define DERMIS_USE_SSS_BLUR_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "SssBlur.glsl"

layout(binding = 0) uniform SSS_CHAIN_SAMPLER uChain;
layout(binding = 1) uniform usampler2D uDepthKey;

#if SSS_PACKED_OUT > 0
layout(location = 0) out uvec4 oBlurred;  // the packed chain: colour and moments
#else  // the colour alone (also the last step that carries the moments: SssBlur.glsl, WHERE THE MOMENTS STOP)
layout(location = 0) out vec4 oBlurred;
#endif
// Blended: rgb += constant colour (w_i) x value, a += constant alpha x value.
layout(location = 1) out vec4 oAccumulate;
#if SSS_EXTRA_TARGETS > 0
layout(location = 2) out vec4 oExtraAccumulate;  // += constant alpha x value
#endif

void main() {
    SssValues blurred = sssBlurStep(uChain, uDepthKey, ivec2(gl_FragCoord.xy));
    vec4 colour = vec4(sanitizeColour(blurred.v[0].rgb), sssSanitizeSigned(blurred.v[0]).a);  // a: 1 or M'.xy
    oAccumulate = colour;
#if SSS_EXTRA_TARGETS > 0
    vec4 extra = sssSanitizeSigned(blurred.v[1]);
    oExtraAccumulate = extra;
#endif
#if SSS_PACKED_OUT > 0
    oBlurred = sssPack(colour, extra);
#else
    oBlurred = colour;
#endif
}
