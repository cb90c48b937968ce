// One direction of one Gaussian step of the screen-space SSS chain; see
// include/SssBlur.glsl for the method, how it is driven and the output
// locations. With SSS_EXTRA_TARGETS > 0 the LEAN moments ride along.
#define DERMIS_USE_SSS_BLUR_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"
#include "SssBlur.glsl"

layout(binding = 0) uniform sampler2D uColour;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oBlurred;
#if SSS_EXTRA_TARGETS > 0
layout(location = 1) out vec4 oExtraBlurred[SSS_EXTRA_TARGETS];
#endif
layout(location = SSS_EXTRA_TARGETS + 1) out vec4 oAccumulate;  // blended: += constant colour (w_i) x value
#if SSS_EXTRA_TARGETS > 0
layout(location = SSS_EXTRA_TARGETS + 2) out vec4 oExtraAccumulate[SSS_EXTRA_TARGETS];  // += constant alpha x value
#endif

void main() {
    SssValues blurred = sssBlurStep(uColour, uDepthKey, ivec2(gl_FragCoord.xy));
    blurred.v[0].rgb = sanitizeColour(blurred.v[0].rgb);
    oBlurred = blurred.v[0];
    oAccumulate = vec4(blurred.v[0].rgb, 0.0);
#if SSS_EXTRA_TARGETS > 0
    for (int k = 0; k < SSS_EXTRA_TARGETS; ++k) {
        vec4 value = sssSanitizeSigned(blurred.v[k + 1]);
        oExtraBlurred[k] = value;
        oExtraAccumulate[k] = value;
    }
#endif
}
