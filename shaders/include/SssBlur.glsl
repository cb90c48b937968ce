// SssBlur.glsl: one separable step of the incremental sum-of-Gaussians
// screen-space SSS blur. This header is its own manual.
//
// WHAT IT DOES
//   d'Eon & Luebke approximate a diffusion profile by a sum of Gaussians,
//   R(r) = sum_i w_i G(v_i, r) (Chappuis 2011 §2.1.4). Because G(a) * G(b) =
//   G(a + b), Gaussian i can be made by blurring the result of Gaussian i-1
//   by the difference of variances (Chappuis 2011 §2.2.4). Each step is separable:
//   a horizontal then a vertical 1-D pass. The vertical pass also adds
//   w_i x result into an accumulation target by blending (Jimenez's running
//   sum, Vila Verde 2015 §3.2.2), so no per-Gaussian textures are kept.
//
// INTEGRATION (engine/passes/SssPasses.cpp does this)
//   1. Per frame, per profile slot, per Gaussian step i, draw a fullscreen
//      triangle twice with this shader: direction (1,0) into a temporary,
//      then direction (0,1) into the next chain texture (location 0) and the
//      accumulation (location 1) with glBlendFuncSeparatei(1,
//      GL_CONSTANT_COLOR, GL_ONE, GL_CONSTANT_ALPHA, GL_ONE) and
//      glBlendColor(w_i, the scalar weight below): RGB by the profile's
//      weights, alpha by the scalar one.
//   2. Bind the G-buffer's depth-stencil as the depth-stencil attachment and
//      set glStencilFunc(GL_EQUAL, slot, 0xFF): only that profile's pixels run.
//      A scissor around its characters trims the rest.
//   3. Fill SssBlurBlock (UniformBlocks.glsl) per draw: the kernel (offsets in
//      standard deviations, computed on the CPU by engine/sss/BlurKernel.cpp;
//      the shader takes its tap spacing from them and integrates its own
//      weights, SAMPLING AND WEIGHTS below), the direction, this step's
//      standard deviation in mm, the edge mode, the profile slot and whether
//      the step reads the unblurred irradiance.
//   4. Bind the chain input to unit 0 and the depth key (G-buffer target 2,
//      R32UI) to unit 1.
//   5. Outputs: location 0 the blurred chain value, 1 the colour's
//      accumulation and, with SSS_EXTRA_TARGETS = 1, 2 the extra target's
//      accumulation, blended with glBlendFunci(2, GL_CONSTANT_ALPHA, GL_ONE)
//      (the per-Gaussian scalar weight is the blend colour's alpha). A
//      horizontal pass attaches location 0 only.
//
// CHAIN, PACKING, EXTRA TARGETS AND EDGES: include/SssChain.glsl, shared
//   with the other techniques.
//
// WIDTH (Chappuis 2011 §2.2.4; docs/screen-space.md, step 6)
//   A step of std dev sigma_mm covers sigma_mm * 1e-3 * P / z pixels at view
//   depth z metres, where P = uFrame.pixelsPerMetreAtUnitDepth is the number of pixels per
//   metre at 1 m (height / (2 tan(fov/2))). World space is in metres, so each
//   character's metres_per_unit is already in z. The centre pixel's depth
//   sets the width, as in Jimenez's SeparableSSS, divided by the skin's
//   stretch along the pass's direction (SssChain.glsl, SLANT).
//
// SAMPLING AND WEIGHTS (per pixel, from its own width in pixels sigma_px)
//   Taps fetch whole texels (texelFetch): a bilinear fetch at a silhouette
//   would mix in a texel the depth test never saw. So the taps sit at whole
//   pixels k_j = j * s, j = -H..H (H = taps / 2), with a whole-pixel spacing
//   s = max(1, round(x_1 * sigma_px)) (x_1: the CPU kernel's first offset in
//   standard deviations, so taps span about its extent). Each tap stands for
//   its cell [k_j - s/2, k_j + s/2] (the outer two reach to infinity) and
//   weighs the Gaussian integrated over that cell, not its point value
//   (Phi from erf, Abramowitz & Stegun 1964 7.1.26), so the weights sum to 1
//   and the width is exact to a fraction of a pixel at every depth.
//   - A step that reads the unblurred irradiance (uSssBlur.readsIrradiance = 1)
//     treats its texels as boxes: with s = 1 the cell integrals are exactly
//     the diffusion of that piecewise-constant image (the box adds its own
//     1/12 px^2, as the true diffusion of the box image does).
//   - A later step reads a blurred, smooth chain, where the cells' own width
//     would add ~s^2/12 px^2 per step (Sheppard's correction) on top of the
//     variance the step must add: there the Gaussian's width sigma' is
//     solved so that the discrete kernel's variance, sum_j w_j k_j^2, is
//     exactly sigma_px^2 (a few fixed-point steps; the variance grows by
//     about as much as sigma'^2 does).
//
// WHERE THE MOMENTS STOP (SSS_PACKED_OUT = 0; engine/plan/SssVariant.h)
//   The moments need not ride through every Gaussian: the wide ones blur the
//   irradiance over millimetres, but change the specular little (the LEAN
//   lobe's detail is sub-pixel, and the view-plane slopes of a face vary
//   slowly), while each packed step costs about a third more than a plain
//   one on llvmpipe. So the moments ride only through the steps up to a
//   cut-off; the last of them is drawn with SSS_PACKED_OUT = 0: it still
//   reads the packed chain and accumulates the moments, but writes the
//   colour alone (location 0 a vec4), and the steps after it run the plain
//   program. The moments' accumulation is finished in that last step: its
//   scalar weight is its own plus that of every later Gaussian (the blend
//   colour's alpha), and the later steps blend alpha with 0, so the cross
//   moment in the colour's alpha stops with the others. The result is still
//   one convex combination of moments (every blurred moment image is one, and
//   the weights still sum to one), the argument of EXTRA TARGETS AND ALPHA.
//
// CONFIGURATION: SSS_EXTRA_TARGETS and SSS_PACKED_OUT, include/SssChain.glsl.
#ifndef DERMIS_SSS_BLUR_GLSL
#define DERMIS_SSS_BLUR_GLSL

#ifndef DERMIS_USE_SSS_BLUR_BLOCK
#error "define DERMIS_USE_SSS_BLUR_BLOCK before including UniformBlocks.glsl"
#endif

#include "SssChain.glsl"

const int kSssMaxHalfTaps = DERMIS_MAX_BLUR_TAPS / 2;

// Cell-integrated weights of taps 0..halfTaps at spacing s px for a Gaussian of
// std dev sigma px (SAMPLING AND WEIGHTS); returns the kernel's variance in px^2.
float sssCellWeights(float sigmaPx, float spacingPx, int halfTaps, out float weights[kSssMaxHalfTaps + 1]) {
    float inverseSigma = 1.0 / max(sigmaPx, 1e-6);
    float lowerTail = normalUpperTail(0.5 * spacingPx * inverseSigma);
    weights[0] = 1.0 - 2.0 * lowerTail;
    float variance = 0.0;
    for (int j = 1; j <= halfTaps; ++j) {
        float upperTail = j == halfTaps ? 0.0 : normalUpperTail((float(j) + 0.5) * spacingPx * inverseSigma);
        weights[j] = lowerTail - upperTail;
        variance += 2.0 * weights[j] * float(j * j) * spacingPx * spacingPx;
        lowerTail = upperTail;
    }
    return variance;
}

// The taps' spacing (whole pixels) and weights for this pixel's width.
float sssTapWeights(float sigmaPx, int halfTaps, bool readsBoxes, out float weights[kSssMaxHalfTaps + 1]) {
    float spacingPx = max(1.0, round(uSssBlur.kernel[halfTaps + 1].x * sigmaPx));
    float variance = sssCellWeights(sigmaPx, spacingPx, halfTaps, weights);
    if (readsBoxes) return spacingPx;
    float target = sigmaPx * sigmaPx;
    float sigma2 = target;
    for (int iteration = 0; iteration < 3; ++iteration) {
        sigma2 = max(sigma2 + target - variance, 1e-6);
        variance = sssCellWeights(sqrt(sigma2), spacingPx, halfTaps, weights);
    }
    return spacingPx;
}

// The blurred values at `pixel` along uSssBlur.direction. Returns the centre
// when the pixel is not on this profile (stencil keeps that from happening;
// this is the belt to its braces).
SssValues sssBlurStep(SSS_CHAIN_SAMPLER colour, usampler2D depthKey, ivec2 pixel) {
    ivec2 size = textureSize(colour, 0);
    SssValues centre;
    uint centreKey;
    float viewDepthM;
    if (!sssCentre(colour, depthKey, pixel, uSssBlur.edges.slot, centre, centreKey, viewDepthM)) return centre;

    vec2 direction = uSssBlur.direction;
    SssSlant slant = sssSlant(depthKey, pixel, ivec2(direction), centreKey, viewDepthM);
    float sigmaPx = uSssBlur.sigmaMm * 1e-3 * uFrame.pixelsPerMetreAtUnitDepth / viewDepthM / slant.stretch;
    int taps = uSssBlur.taps;
    int halfTaps = min(taps / 2, kSssMaxHalfTaps);
    float halfWeights[kSssMaxHalfTaps + 1];
    float spacingPx = sssTapWeights(sigmaPx, halfTaps, uSssBlur.readsIrradiance != 0, halfWeights);
    SssRejected rejected = sssRejected(centre, pixel, sssSlope(slant));

    SssValues sum;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] = vec4(0.0);
    float weightSum = 0.0;
    for (int j = -halfTaps; j <= halfTaps; ++j) {
        ivec2 tapPixel = clamp(pixel + ivec2(direction * (float(j) * spacingPx)), ivec2(0), size - 1);
        float weight = halfWeights[abs(j)];
        SssEdgeTap edge = sssEdgeTap(centreKey, texelFetch(depthKey, tapPixel, 0).r,
                                     float(j) * spacingPx * slant.depthPerPxM, uSssBlur.edges);
        if (edge.weight <= 0.0) continue;
        weight *= edge.weight;
        SssValues toward = sssRejectedFor(rejected, edge);
        if (edge.toCentre < 1.0) {
            SssValues tap = sssFetch(colour, tapPixel);
            for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] += weight * mix(tap.v[k], toward.v[k], edge.toCentre);
        } else {
            for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] += weight * toward.v[k];
        }
        weightSum += weight;
    }
    if (!(weightSum > 0.0)) return centre;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] /= weightSum;
    return sum;
}

#endif
