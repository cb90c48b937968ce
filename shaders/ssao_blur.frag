// Bilateral blur of the raw SSAO (docs/screen-space.md, step 3), one pass.
//
// INTEGRATION
//   Program: fullscreen.vert + ssao_blur.frag (Programs::ssaoBlur), driven by
//   engine/passes/SsaoPass.cpp. Fullscreen triangle into an R8 target of the
//   raw AO's size. Inputs:
//     unit 0  uAo        raw AO from ssao.frag (R8, 1 = unoccluded)
//     unit 1  uDepthKey  G-buffer R32UI depth key: profile slot and view
//                        depth packed (UniformBlocks.glsl)
//     SsaoBlock (DERMIS_BINDING_PASS):
//       blur.x  half width in pixels, 0..4 (0 copies)         default 2 (5x5)
//       blur.y  depth tolerance as a fraction of the centre's  default 0.05
//               view depth
//
// METHOD
//   A box of (2 blur.x + 1)^2 taps around the pixel; each tap's weight is
//   max(0, 1 - |key_tap - key_centre| / tolerance). Because the key adds
//   1000 m per profile slot and 1e7 m on the background, the one depth test
//   keeps AO from bleeding across silhouettes, between SSS profiles and
//   into the background. The box (rather than a Gaussian) suits the
//   per-pixel rotation noise of ssao.frag, which decorrelates neighbours.
//   The centre tap always has weight 1, so the sum never divides by zero.
#define DERMIS_USE_SSAO_BLOCK
#include "Common.glsl"
#include "UniformBlocks.glsl"

layout(binding = 0) uniform sampler2D uAo;
layout(binding = 1) uniform usampler2D uDepthKey;

layout(location = 0) out vec4 oAo;

const int kMaxHalfWidthPx = 4;

float blurredAo(ivec2 pixel) {
    uint centreKey = texelFetch(uDepthKey, pixel, 0).r;
    if (isBackgroundKey(centreKey)) return 1.0;
    float viewDepthM = max(viewDepthFromKey(centreKey), 1e-3);
    float toleranceMm = max(uSsao.blurDepthTolerance * viewDepthM, 1e-5) * 1000.0;
    int halfWidth = clamp(uSsao.blurHalfWidthPx, 0, kMaxHalfWidthPx);
    ivec2 last = textureSize(uAo, 0) - 1;

    float sum = 0.0;
    float weightSum = 0.0;
    for (int dy = -halfWidth; dy <= halfWidth; ++dy) {
        for (int dx = -halfWidth; dx <= halfWidth; ++dx) {
            ivec2 tap = clamp(pixel + ivec2(dx, dy), ivec2(0), last);
            float differenceMm = keyDistanceMm(centreKey, texelFetch(uDepthKey, tap, 0).r);
            float weight = differenceMm < toleranceMm ? 1.0 - differenceMm / toleranceMm : 0.0;
            sum += weight * texelFetch(uAo, tap, 0).r;
            weightSum += weight;
        }
    }
    float ao = sum / max(weightSum, kTiny);
    return sanitiseRange(ao, 0.0, 1.0, 1.0);
}

void main() {
    oAo = vec4(blurredAo(ivec2(gl_FragCoord.xy)));
}
