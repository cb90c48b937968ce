// Texture-space step 3: chart gutters are dilated (include/TextureSpace.glsl).
// A covered texel (alpha > 0) is copied; an empty one takes the nearest
// covered texel found along the 8 principal directions within
// uTs.dilationTexels texels, or stays empty. Blur taps that cross a chart's edge
// then read light from the edge, not black.
#define DERMIS_USE_TS_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uIrradiance;

layout(location = 0) out vec4 oIrradiance;

const ivec2 kDirections[8] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1), ivec2(1, 1), ivec2(-1, 1),
                                     ivec2(1, -1), ivec2(-1, -1));

void shade() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 centre = texelFetch(uIrradiance, texel, 0);
    if (centre.a > 0.0) {
        oIrradiance = centre;
        return;
    }
    ivec2 size = textureSize(uIrradiance, 0);
    int radius = int(uTs.dilationTexels);
    for (int r = 1; r <= radius; ++r) {
        for (int d = 0; d < 8; ++d) {
            ivec2 p = texel + kDirections[d] * r;
            if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size))) continue;
            vec4 value = texelFetch(uIrradiance, p, 0);
            if (value.a > 0.0) {
                oIrradiance = value;
                return;
            }
        }
    }
    oIrradiance = vec4(0.0);
}

// The pass's output goes through the planted NaN of docs/stress.md.
void main() {
    shade();
    oIrradiance = debugPlant(oIrradiance);
}
