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
// EXTRA TARGETS AND ALPHA (the LEAN moments, include/Lean.glsl)
//   The colour's alpha (1, or in the LEAN variants the cross moment M'.xy)
//   and every extra target (B'.x, B'.y, M'.xx, M'.yy) are blurred with the
//   very taps and weights of the colour, in the same draw (Vila Verde 2015 blurred four textures in four passes,
//   about 4x the cost of the control blur; here the taps' depth keys and
//   weights are computed once). Their accumulation weight per Gaussian is one
//   scalar (alpha and extra targets alike), the mean of the Gaussian's RGB
//   weights (engine/render/SssVariant.h),
//   because:
//   - the profile's weights are normalised per channel, so the means also
//     sum to one with the identity weight: the accumulated moments are a
//     convex combination of moments, i.e. the moments of a mixture, whose
//     covariance M - B B^T is positive semi-definite (a per-channel or
//     per-target weight would not be: B and M must come from one mixture);
//   - every step above is itself convex (bilateral: renormalised weights;
//     control: a lerp towards the centre), so nothing leaves that set;
//   - the specular lobe is white: no channel of the profile has a claim on
//     it, and the mean is the profile's average reach.
//   An alpha of 1 therefore stays 1.
//
// PACKING (SSS_EXTRA_TARGETS = 1)
//   Colour (RGBA) and extra target (RGBA) are eight halves; the chain keeps
//   them in one RGBA32UI texture, two halves per channel (packHalf2x16, the
//   fp16 the float targets would store), so a tap is one fetch of the chain
//   and one of the key, as in the plain blur. The chain starts in sss_init,
//   which packs the irradiance and the G-buffer's moments; the accumulations
//   stay float, blended through multiple render targets. M'.xy rides in the
//   irradiance's alpha, so the five moments and the irradiance fill exactly
//   the eight halves. (On llvmpipe the fetches are the blur's cost; a GPU
//   reads the same 16 bytes a tap either way.)
//
// WIDTH (Chappuis 2011 §2.2.4; docs/screen-space.md, step 6)
//   A step of std dev sigma_mm covers sigma_mm * 1e-3 * P / z pixels at view
//   depth z metres, where P = uFrame.features.y is the number of pixels per
//   metre at 1 m (height / (2 tan(fov/2))). World space is in metres, so each
//   character's metres_per_unit is already in z. The centre pixel's depth
//   sets the width, as in Jimenez's SeparableSSS.
//
// EDGES (include/SssEdges.glsl, shared with the other techniques)
//   bilateral (the default of lbb), control (c, lcb) or fetch-only (the
//   benchmarks' bandwidth floor: the same fetches of colour and key per tap,
//   summed with the kernel weights and nothing else).
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
//   - A step that reads the unblurred irradiance (uSssBlur.source.x = 1)
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
// WHERE THE MOMENTS STOP (SSS_PACKED_OUT = 0; engine/render/SssVariant.h)
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
// CONFIGURATION (define before including)
//   SSS_EXTRA_TARGETS  0 (default) or 1: one extra RGBA target (the LEAN
//                      moments) blurred with the same taps; the chain is then
//                      packed (PACKING above) and SSS_CHAIN_SAMPLER is a
//                      usampler2D.
//   SSS_PACKED_OUT     with SSS_EXTRA_TARGETS = 1 only: 1 (default) writes the
//                      packed chain, 0 writes the colour alone (WHERE THE
//                      MOMENTS STOP). Read by sss_blur.frag.
#ifndef DERMIS_SSS_BLUR_GLSL
#define DERMIS_SSS_BLUR_GLSL

#include "SssEdges.glsl"

#ifndef SSS_EXTRA_TARGETS
#define SSS_EXTRA_TARGETS 0
#endif
#if SSS_EXTRA_TARGETS < 0 || SSS_EXTRA_TARGETS > 1
#error "SSS_EXTRA_TARGETS must be 0 or 1"
#endif

#ifndef SSS_PACKED_OUT
#define SSS_PACKED_OUT SSS_EXTRA_TARGETS
#endif
#if SSS_PACKED_OUT < 0 || SSS_PACKED_OUT > SSS_EXTRA_TARGETS
#error "SSS_PACKED_OUT must be 0 or 1, and 1 only with SSS_EXTRA_TARGETS = 1"
#endif

#define SSS_VALUES (1 + SSS_EXTRA_TARGETS)
#if SSS_EXTRA_TARGETS > 0
#define SSS_CHAIN_SAMPLER usampler2D
#else
#define SSS_CHAIN_SAMPLER sampler2D
#endif

// The colour ([0]) and the extra target ([1]) at one pixel.
struct SssValues {
    vec4 v[SSS_VALUES];
};

SssValues sssFetch(SSS_CHAIN_SAMPLER chain, ivec2 pixel) {
    SssValues values;
#if SSS_EXTRA_TARGETS > 0
    uvec4 halves = texelFetch(chain, pixel, 0);
    values.v[0] = vec4(unpackHalf2x16(halves.x), unpackHalf2x16(halves.y));
    values.v[1] = vec4(unpackHalf2x16(halves.z), unpackHalf2x16(halves.w));
#else
    values.v[0] = texelFetch(chain, pixel, 0);
#endif
    return values;
}

// The centre of every technique's step at `pixel`: its values, its depth key
// and view depth; false when it is not on `slot` or has no depth (the stencil
// keeps such pixels away; this is the belt to its braces).
bool sssCentre(SSS_CHAIN_SAMPLER chain, usampler2D depthKey, ivec2 pixel, int slot, out SssValues values, out uint key,
               out float viewDepthM) {
    values = sssFetch(chain, pixel);
    key = texelFetch(depthKey, pixel, 0).r;
    viewDepthM = viewDepthFromKey(key);
    return slotFromKey(key) == slot && viewDepthM > 0.0;
}

#if SSS_EXTRA_TARGETS > 0
// The chain texel of sanitised values (sssSanitizeSigned / sanitizeColour).
uvec4 sssPack(vec4 colour, vec4 extra) {
    return uvec4(packHalf2x16(colour.rg), packHalf2x16(colour.ba), packHalf2x16(extra.rg), packHalf2x16(extra.ba));
}
#endif

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

// The blurred values at `pixel` along uSssBlur.step.xy. Returns the centre
// when the pixel is not on this profile (stencil keeps that from happening;
// this is the belt to its braces).
SssValues sssBlurStep(SSS_CHAIN_SAMPLER colour, usampler2D depthKey, ivec2 pixel) {
    ivec2 size = textureSize(colour, 0);
    SssValues centre;
    uint centreKey;
    float viewDepthM;
    if (!sssCentre(colour, depthKey, pixel, int(uSssBlur.edges.w), centre, centreKey, viewDepthM)) return centre;

    float sigmaPx = uSssBlur.step.z * 1e-3 * uFrame.features.y / viewDepthM;
    vec2 direction = uSssBlur.step.xy;
    int taps = int(uSssBlur.step.w);
    int halfTaps = min(taps / 2, kSssMaxHalfTaps);
    float halfWeights[kSssMaxHalfTaps + 1];
    float spacingPx = sssTapWeights(sigmaPx, halfTaps, uSssBlur.source.x > 0.5, halfWeights);
    int edges = int(uSssBlur.edges.x + 0.5);
    bool fetchOnly = edges == DERMIS_BLUR_EDGES_FETCH_ONLY;

    SssValues sum;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] = vec4(0.0);
    float weightSum = 0.0;
    for (int j = -halfTaps; j <= halfTaps; ++j) {
        ivec2 tapPixel = clamp(pixel + ivec2(direction * (float(j) * spacingPx)), ivec2(0), size - 1);
        float weight = halfWeights[abs(j)];
        if (fetchOnly) {
            SssValues tap = sssFetch(colour, tapPixel);
            tap.v[0].a = float(texelFetch(depthKey, tapPixel, 0).r & 255u);
            for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] += weight * tap.v[k];
            weightSum += weight;
            continue;
        }
        SssEdgeTap edge = sssEdgeTap(centreKey, texelFetch(depthKey, tapPixel, 0).r, edges, uSssBlur.edges.y,
                                     uSssBlur.edges.z);
        if (edge.weight <= 0.0) continue;
        weight *= edge.weight;
        if (edge.toCentre < 1.0) {
            SssValues tap = sssFetch(colour, tapPixel);
            for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] += weight * mix(tap.v[k], centre.v[k], edge.toCentre);
        } else {
            for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] += weight * centre.v[k];
        }
        weightSum += weight;
    }
    if (!(weightSum > 0.0)) return centre;
    for (int k = 0; k < SSS_VALUES; ++k) sum.v[k] /= weightSum;
    return sum;
}

// Keeps a signed value (a LEAN moment) storable in fp16 and free of NaN, so
// one bad texel cannot spread through the chain.
vec4 sssSanitizeSigned(vec4 value) {
    return sanitiseRange(value, -kHalfMax, kHalfMax);
}

#endif
