// Exposure, a filmic curve and sRGB encoding into an 8-bit target.
// The curve is Narkowicz's fit of the ACES reference rendering transform.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uColour;

in vec2 vUv;
layout(location = 0) out vec4 oColour;

vec3 acesFilm(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

vec3 encodeSrgb(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(max(linear, vec3(0.0)), vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

void main() {
    vec3 colour = sanitizeColour(texture(uColour, vUv).rgb) * uFrame.exposure;
    oColour = vec4(encodeSrgb(acesFilm(colour)), 1.0);
}
