// SeparableSss.glsl: one direction of Separable Subsurface Scattering
// (Jimenez et al. 2015) in screen space. This header is its own manual.
//
// WHAT IT DOES
//   The whole diffusion profile R in two 1-D passes (horizontal, then
//   vertical) with one pre-integrated kernel K, the marginal of R (its line
//   integral across the blur direction), instead of one pass pair per
//   Gaussian as the d'Eon chain (SssBlur.glsl) does. Two passes apply
//   K(x) K(y): exactly R for one Gaussian, a rank-1 approximation of R for a
//   sum (docs/screen-space.md, "Separable kernel", has its measured error).
//   Across a straight edge along a blur axis the result is still exact: the
//   marginal of K(x) K(y) is K.
//
// INTEGRATION (engine/passes/SssSeparablePasses.cpp does this)
//   1. After `sss init`, per profile slot whose technique is separable, draw
//      a fullscreen triangle twice: SEPARABLE_SSS_LAST = 0, direction (1,0),
//      reading the chain start (the irradiance, or the packed chain of the
//      LEAN variants) into a temporary of the chain's format; then
//      SEPARABLE_SSS_LAST = 1, direction (0,1), reading that temporary and
//      writing the result into the accumulation(s), no blending: the result
//      replaces what sss init put there (the identity weight is part of K).
//   2. Bind the G-buffer's depth-stencil as the depth-stencil attachment and
//      set glStencilFunc(GL_EQUAL, slot, 0xFF) with a scissor around the
//      slot's characters: only the slot's pixels run, every other pixel of
//      the accumulation keeps its value.
//   3. Fill SeparableSssBlock (UniformBlocks.glsl): the taps of
//      engine/sss/SeparableKernel.h (offsets in mm, already times the slot's
//      width scale; RGB weights summing to 1 per channel), direction, tap
//      count, edge mode and slot.
//   4. Units: 0 the chain input, 1 the depth key (G-buffer target 2, R32UI).
//   5. Outputs, SEPARABLE_SSS_LAST = 0: location 0 the chain value (packed
//      with SSS_EXTRA_TARGETS = 1). SEPARABLE_SSS_LAST = 1: location 0 the
//      colour's accumulation and, with SSS_EXTRA_TARGETS = 1, location 1 the
//      extra target's.
//
// WIDTH (as SssBlur.glsl, WIDTH)
//   A tap at x mm sits x * 1e-3 * P / z pixels from the centre, z the
//   centre's view depth (m), P = uFrame.features.y (pixels per metre at 1 m).
//
// FRACTIONAL TAPS: WHOLE TEXELS, MERGED
//   Each tap reads the whole texel nearest to its position (texelFetch of
//   round(offset px)), never a bilinear mix: a bilinear fetch at a
//   silhouette would blend in a texel the depth test never saw. Successive
//   taps that land on the same texel are merged (their weights summed, one
//   fetch and one edge test), so the skin's many sub-pixel taps near the
//   centre cost one fetch at ordinary distances. Rounding moves each tap's
//   weight by up to half a pixel; on the analytic edge this is measured in
//   tests/render/test_separable_sss.cpp (docs/screen-space.md, "Separable
//   SSS").
//
// EDGES (include/SssEdges.glsl, shared with the other techniques)
//   bilateral: a tap's weight is multiplied by the depth test's weight and
//   the sum is renormalised per channel (and for the scalar weight, below);
//   control: the tap's value is lerped to the centre's, weights unchanged;
//   fetch-only: the benchmarks' floor.
//
// EXTRA TARGETS AND ALPHA
//   As in SssBlur.glsl ("EXTRA TARGETS AND ALPHA"): the colour's alpha and
//   the extra target (the LEAN moments) go through the very same taps with
//   one scalar weight per tap, the mean of its RGB weights, renormalised by
//   their own sum: a convex combination, so the moments stay the moments of
//   a mixture and an alpha of 1 stays 1.
//
// CONFIGURATION (define before including)
//   SSS_EXTRA_TARGETS   0 (default) or 1, as SssBlur.glsl (the packed chain).
//   SEPARABLE_SSS_LAST  0 (default): the horizontal pass, writing the chain;
//                       1: the vertical pass, writing the accumulations.
#ifndef DERMIS_SEPARABLE_SSS_GLSL
#define DERMIS_SEPARABLE_SSS_GLSL

#ifndef SEPARABLE_SSS_LAST
#define SEPARABLE_SSS_LAST 0
#endif
#if SEPARABLE_SSS_LAST < 0 || SEPARABLE_SSS_LAST > 1
#error "SEPARABLE_SSS_LAST must be 0 or 1"
#endif
#ifndef DERMIS_USE_SEPARABLE_SSS_BLOCK
#error "define DERMIS_USE_SEPARABLE_SSS_BLOCK before including UniformBlocks.glsl"
#endif

#include "SssBlur.glsl"

// The scalar weight of a tap's alpha and extra target: the mean of its RGB weights.
float separableScalarWeight(vec3 weight) {
    return (weight.r + weight.g + weight.b) / 3.0;
}

// The blurred values at `pixel` along uSeparableSss.step.xy. Returns the
// centre when the pixel is not on this slot (the stencil keeps that from
// happening).
SssValues separableSssStep(SSS_CHAIN_SAMPLER chain, usampler2D depthKey, ivec2 pixel) {
    ivec2 size = textureSize(chain, 0);
    SssValues centre = sssFetch(chain, pixel);
    uint centreKey = texelFetch(depthKey, pixel, 0).r;
    float viewDepthM = viewDepthFromKey(centreKey);
    if (slotFromKey(centreKey) != int(uSeparableSss.edges.w) || viewDepthM <= 0.0) return centre;

    float pixelsPerMm = 1e-3 * uFrame.features.y / viewDepthM;
    ivec2 direction = ivec2(uSeparableSss.step.xy);
    int count = min(int(uSeparableSss.step.z), DERMIS_MAX_SEPARABLE_SAMPLES);
    int edges = int(uSeparableSss.edges.x + 0.5);

    SssValues sum;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] = vec4(0.0);
    vec3 weightSum = vec3(0.0);
    float scalarSum = 0.0;
    int i = 0;
    while (i < count) {
        int offsetPx = int(round(uSeparableSss.taps[i].a * pixelsPerMm));
        vec3 weight = uSeparableSss.taps[i].rgb;
        while (i + 1 < count && int(round(uSeparableSss.taps[i + 1].a * pixelsPerMm)) == offsetPx) {
            weight += uSeparableSss.taps[i + 1].rgb;
            ++i;
        }
        ++i;
        SssValues tap = centre;
        if (offsetPx != 0) {
            ivec2 tapPixel = clamp(pixel + direction * offsetPx, ivec2(0), size - 1);
            SssEdgeTap edge = sssEdgeTap(centreKey, texelFetch(depthKey, tapPixel, 0).r, edges,
                                         uSeparableSss.edges.y, uSeparableSss.edges.z);
            if (edge.weight <= 0.0) continue;
            weight *= edge.weight;
            if (edge.toCentre < 1.0) {
                tap = sssFetch(chain, tapPixel);
                for (int k = 0; k < SSS_VALUES; ++k) tap.v[k] = mix(tap.v[k], centre.v[k], edge.toCentre);
            }
        }
        float scalar = separableScalarWeight(weight);
        sum.v[0] += vec4(weight * tap.v[0].rgb, scalar * tap.v[0].a);
        for (int k = 1; k < SSS_VALUES; ++k) sum.v[k] += scalar * tap.v[k];
        weightSum += weight;
        scalarSum += scalar;
    }
    if (!(weightSum.r > 0.0 && weightSum.g > 0.0 && weightSum.b > 0.0 && scalarSum > 0.0)) return centre;
    // Per channel: taps dropped at an edge took their own share of each channel's weight.
    sum.v[0] /= vec4(weightSum, scalarSum);
    for (int k = 1; k < SSS_VALUES; ++k) sum.v[k] /= scalarSum;
    return sum;
}

#endif
