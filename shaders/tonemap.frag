// Exposure, the tone map settings.tone_map names (DERMIS_TONE_MAP_*) and sRGB
// encoding into an 8-bit target. Each curve takes linear scene-referred RGB
// and returns linear display RGB in [0, 1], which encodeSrgb then encodes.
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uColour;

in vec2 vUv;
layout(location = 0) out vec4 oColour;

// Narkowicz 2016, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES
// reference rendering transform and output transform.
vec3 acesFilm(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Khronos 2024, "Khronos PBR Neutral Tone Mapper": colours below the start of
// compression pass unchanged (but for a small offset that darkens the
// blacks); above it the peak channel is compressed toward 1 and the colour
// desaturated toward its new peak.
vec3 pbrNeutral(vec3 colour) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(colour.r, min(colour.g, colour.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    colour -= offset;
    float peak = max(colour.r, max(colour.g, colour.b));
    if (peak < startCompression) return colour;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    colour *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(colour, vec3(newPeak), g);
}

// AgX (Sobotka 2022): the inset matrix, a log2 encoding over [-12.47, 4.03]
// EV around middle grey, the base contrast curve as Wrensch 2023's
// sixth-order polynomial fit, the outset matrix; the curve's output is display
// encoded with a 2.2 power, undone here so that encodeSrgb applies.
vec3 agx(vec3 colour) {
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float minEv = -12.47393;
    const float maxEv = 4.026069;
    vec3 x = inset * max(colour, vec3(1e-10));
    x = (clamp(log2(x), minEv, maxEv) - minEv) / (maxEv - minEv);
    vec3 x2 = x * x;
    vec3 x4 = x2 * x2;
    x = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
    return pow(clamp(outset * x, 0.0, 1.0), vec3(2.2));
}

vec3 encodeSrgb(vec3 linear) {
    vec3 low = linear * 12.92;
    vec3 high = 1.055 * pow(max(linear, vec3(0.0)), vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(linear, vec3(0.0031308)));
}

void main() {
    vec3 colour = sanitizeColour(texture(uColour, vUv).rgb) * uFrame.exposure;
    vec3 display;
    if (uFrame.toneMap == DERMIS_TONE_MAP_PBR_NEUTRAL) {
        display = pbrNeutral(colour);
    } else if (uFrame.toneMap == DERMIS_TONE_MAP_AGX) {
        display = agx(colour);
    } else if (uFrame.toneMap == DERMIS_TONE_MAP_NONE) {
        display = colour;
    } else {
        display = acesFilm(colour);
    }
    oColour = vec4(encodeSrgb(clamp(display, 0.0, 1.0)), 1.0);
}
