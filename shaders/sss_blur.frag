// One direction of one Gaussian step of the screen-space SSS chain; see
// include/SssBlur.glsl for the method and how it is driven.
#define DERMIS_USE_SSS_BLUR_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "SssBlur.glsl"

layout(binding = 0) uniform sampler2D uColour;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oBlurred;
layout(location = 1) out vec4 oAccumulate;  // blended: += constant colour (w_i) x value

void main() {
    vec4 blurred = sssBlurStep(uColour, uDepthKey, ivec2(gl_FragCoord.xy));
    blurred.rgb = sanitizeColour(blurred.rgb);
    oBlurred = blurred;
    oAccumulate = vec4(blurred.rgb, 0.0);
}
