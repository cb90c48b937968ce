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
//   centre's view depth (m), P = uFrame.pixelsPerMetreAtUnitDepth (pixels per metre at 1 m).
//
// FRACTIONAL TAPS: WHOLE TEXELS, SPLIT AND MERGED
//   A tap's position is rarely a whole pixel. It is never fetched bilinearly
//   (as Jimenez et al.'s shader does): at a silhouette that would blend in a
//   texel the depth test never saw. Instead (SEPARABLE_SSS_FETCH = 1) its
//   weight is split linearly between the two whole texels around it, each
//   fetched with texelFetch and edge-tested on its own: the tap's mean
//   position is kept exactly. Contributions that land on the same texel
//   (skin's many sub-pixel taps near the centre) are merged into one fetch
//   and one edge test. SEPARABLE_SSS_FETCH = 0 rounds each tap to its nearest
//   texel instead (one fetch per tap, as the d'Eon chain's whole-pixel taps):
//   it moves the heavy inner taps towards the centre, and on the analytic
//   edge the kernel then fits 15% narrower in green and blue (docs/screen-
//   space.md, "Separable SSS", has both measured).
//
// EDGES (include/SssEdges.glsl, shared with the other techniques)
//   bilateral: the tap's value is lerped to the centre's by 1 - the depth
//   test's Gaussian; control: linearly in the depth difference; weights
//   unchanged, and the sum divided per channel by them (and for the scalar
//   weight, below); fetch-only: the benchmarks' floor.
//
// EXTRA TARGETS AND ALPHA
//   As in SssChain.glsl ("EXTRA TARGETS AND ALPHA"): the colour's alpha and
//   the extra target (the LEAN moments) go through the very same taps with
//   one scalar weight per tap, the mean of its RGB weights, renormalised by
//   their own sum: a convex combination, so the moments stay the moments of
//   a mixture and an alpha of 1 stays 1.
//
// CONFIGURATION (define before including)
//   SSS_EXTRA_TARGETS   0 (default) or 1, as SssChain.glsl (the packed chain).
//   SEPARABLE_SSS_LAST  0 (default): the horizontal pass, writing the chain;
//                       1: the vertical pass, writing the accumulations.
//   SEPARABLE_SSS_FETCH 1 (default): a tap's weight split between the two
//                       texels around it; 0: the nearest texel (FRACTIONAL TAPS).
#ifndef DERMIS_SEPARABLE_SSS_GLSL
#define DERMIS_SEPARABLE_SSS_GLSL

#ifndef SEPARABLE_SSS_LAST
#define SEPARABLE_SSS_LAST 0
#endif
#if SEPARABLE_SSS_LAST < 0 || SEPARABLE_SSS_LAST > 1
#error "SEPARABLE_SSS_LAST must be 0 or 1"
#endif
#ifndef SEPARABLE_SSS_FETCH
#define SEPARABLE_SSS_FETCH 1
#endif
#if SEPARABLE_SSS_FETCH < 0 || SEPARABLE_SSS_FETCH > 1
#error "SEPARABLE_SSS_FETCH must be 0 or 1"
#endif
#ifndef DERMIS_USE_SEPARABLE_SSS_BLOCK
#error "define DERMIS_USE_SEPARABLE_SSS_BLOCK before including UniformBlocks.glsl"
#endif

#include "SssChain.glsl"

// The scalar weight of a tap's alpha and extra target: the mean of its RGB weights.
float separableScalarWeight(vec3 weight) {
    return (weight.r + weight.g + weight.b) / 3.0;
}

// The blurred values at `pixel` along uSeparableSss.step.xy. Returns the
// centre when the pixel is not on this slot (the stencil keeps that from
// happening).
SssValues separableSssStep(SSS_CHAIN_SAMPLER chain, usampler2D depthKey, ivec2 pixel) {
    ivec2 size = textureSize(chain, 0);
    SssValues centre;
    uint centreKey;
    float viewDepthM;
    if (!sssCentre(chain, depthKey, pixel, uSeparableSss.edges.slot, centre, centreKey, viewDepthM)) return centre;

    ivec2 direction = uSeparableSss.direction;
    SssSlant slant = sssSlant(depthKey, pixel, direction, centreKey, viewDepthM);
    float pixelsPerMm = 1e-3 * uFrame.pixelsPerMetreAtUnitDepth / viewDepthM / slant.stretch;
    int count = min(uSeparableSss.tapCount, DERMIS_MAX_SEPARABLE_SAMPLES);
    SssRejected rejected = sssRejected(centre, pixel, sssSlope(slant));

    SssValues sum;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] = vec4(0.0);
    vec3 weightSum = vec3(0.0);
    float scalarSum = 0.0;
    // Contributions to whole texels, in ascending order of offset: each tap gives one
    // (SEPARABLE_SSS_FETCH 0) or two (1); consecutive ones on the same texel are merged into
    // `pending` and fetched once.
    int pendingOffset = 0;
    vec3 pendingWeight = vec3(0.0);
    for (int i = 0; i <= count; ++i) {
        int offsets[2];
        vec3 weights[2];
        int parts = 0;
        if (i < count) {
            float offsetPx = uSeparableSss.taps[i].a * pixelsPerMm;
#if SEPARABLE_SSS_FETCH == 0
            offsets[0] = int(round(offsetPx));
            weights[0] = uSeparableSss.taps[i].rgb;
            parts = 1;
#else
            float below = floor(offsetPx);
            float above = offsetPx - below;
            offsets[0] = int(below);
            weights[0] = (1.0 - above) * uSeparableSss.taps[i].rgb;
            offsets[1] = int(below) + 1;
            weights[1] = above * uSeparableSss.taps[i].rgb;
            parts = above > 0.0 ? 2 : 1;
#endif
        }
        for (int part = 0; part <= parts; ++part) {
            // part == parts flushes what is pending when the next contribution is elsewhere (or at the end).
            bool last = i == count;
            if (part < parts && offsets[part] == pendingOffset) {
                pendingWeight += weights[part];
                continue;
            }
            if (part == parts && !last) break;
            if (any(greaterThan(pendingWeight, vec3(0.0)))) {
                vec3 weight = pendingWeight;
                SssValues tap = centre;
                bool use = true;
                if (pendingOffset != 0) {
                    ivec2 tapPixel = clamp(pixel + direction * pendingOffset, ivec2(0), size - 1);
                    SssEdgeTap edge = sssEdgeTap(centreKey, texelFetch(depthKey, tapPixel, 0).r,
                                                 float(pendingOffset) * slant.depthPerPxM, uSeparableSss.edges);
                    use = edge.weight > 0.0;
                    weight *= edge.weight;
                    SssValues toward = sssRejectedFor(rejected, edge);
                    tap = toward;
                    if (use && edge.toCentre < 1.0) {
                        tap = sssFetch(chain, tapPixel);
                        for (int k = 0; k < SSS_VALUES; ++k) tap.v[k] = mix(tap.v[k], toward.v[k], edge.toCentre);
                    }
                }
                if (use) {
                    float scalar = separableScalarWeight(weight);
                    sum.v[0] += vec4(weight * tap.v[0].rgb, scalar * tap.v[0].a);
                    for (int k = 1; k < SSS_VALUES; ++k) sum.v[k] += scalar * tap.v[k];
                    weightSum += weight;
                    scalarSum += scalar;
                }
            }
            if (part < parts) {
                pendingOffset = offsets[part];
                pendingWeight = weights[part];
            }
        }
    }
    if (!(weightSum.r > 0.0 && weightSum.g > 0.0 && weightSum.b > 0.0 && scalarSum > 0.0)) return centre;
    // Per channel: taps dropped at an edge took their own share of each channel's weight.
    sum.v[0] /= vec4(weightSum, scalarSum);
    for (int k = 1; k < SSS_VALUES; ++k) sum.v[k] /= scalarSum;
    return sum;
}

#endif
