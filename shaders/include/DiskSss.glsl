// DiskSss.glsl: screen-space SSS by sampling the diffusion profile on a disk
// around each pixel, in one pass. This header is its own manual.
//
// WHAT IT DOES
//   Christensen & Burley 2015 §5 render their normalized diffusion by
//   importance-sampling its radial CDF; Unity HDRP does it in screen space in
//   one pass per pixel (Golubev 2018). The diffused irradiance at a pixel is
//   M(x) = integral R(|x - y|) E(y) dy ~ sum_k w_k E(x + o_k), with offsets o_k
//   whose radii follow the profile and RGB weights w_k = R(r_k) / pdf(r_k),
//   normalised per channel. The kernel is computed on the CPU
//   (engine/sss/DiskKernel.h): radii from the inverse of the radial CDF (Burley's
//   closed form for a Burley profile, the exact profile and not its Gaussian
//   fit; the Gaussians' CDF otherwise) at stratified u_k, angles on a
//   golden-angle spiral. Unlike the d'Eon chain (SssBlur.glsl) it needs no
//   Gaussians and no chain of passes, and it is noisy: the error is sampling
//   noise that falls as the sample count grows, fixed in the image (below).
//
// INTEGRATION (engine/passes/SssDiskPass.cpp does this)
//   1. After sss init (sss_init.frag), per profile slot that uses the disk,
//      draw a fullscreen triangle (or the slot's screen regions) with this
//      shader into the accumulation (location 0) and, with
//      SSS_EXTRA_TARGETS = 1, the extra target's accumulation (location 1).
//      No blending: the pass overwrites its slot's pixels, whatever sss init
//      put there.
//   2. Bind the G-buffer's depth-stencil and set glStencilFunc(GL_EQUAL,
//      slot, 0xFF), and a scissor around the slot's characters, as the d'Eon
//      chain does.
//   3. Fill DiskSssBlock (UniformBlocks.glsl): per sample the unrotated offset
//      (mm), its radius, its RGB weight and the scalar weight of the moments;
//      the sample count, the slot, the largest radius, the edge mode.
//   4. Bind the chain start (the irradiance, or sss init's packed chain with
//      SSS_EXTRA_TARGETS = 1) to unit 0 and the depth key to unit 1.
//
// SAMPLES
//   - Rotation: the spiral is turned per pixel by an angle from a hash of the
//     pixel's coordinates (hashToUnit, Common.glsl), so neighbours sample
//     different directions and the error is spatially decorrelated noise
//     rather than a structured pattern; it is deterministic, so the image is
//     the same every frame and run (no temporal accumulation here, unlike
//     HDRP, which jitters per frame and relies on TAA).
//   - Width: as SssBlur.glsl's WIDTH: r mm covers r * 1e-3 * P / z pixels at
//     the centre's view depth z (P = uFrame.pixelsPerMetreAtUnitDepth).
//   - Fetches: each sample reads the texel its offset rounds to (texelFetch;
//     a bilinear fetch at a silhouette would mix in a texel the edge test
//     never saw), so the irradiance is taken as boxes, as the d'Eon chain's
//     first step does. Offsets are clamped to the frame.
//   - Skip: when the largest sample radius is under half a pixel every sample
//     rounds to the centre, so the centre is output without fetching (HDRP
//     skips below one pixel of its filter radius; at half a pixel the skip
//     changes nothing).
//
// EDGES (include/SssEdges.glsl, shared with the d'Eon chain)
//   Each sample goes through sssEdgeTap: both edges lerp a rejected sample's
//   value to the centre's (bilateral by the depth test's Gaussian, control
//   linearly), so light that the edge test keeps out neither crosses the
//   edge nor darkens the result. The sums are divided per channel by the
//   sum of the weights used.
//
// EXTRA TARGETS AND ALPHA
//   As SssChain.glsl's section of that name: the colour's alpha and the extra
//   target go through the same samples with one scalar weight per sample, the
//   mean of its RGB weights, so the accumulated moments stay a convex
//   combination of moments.
//
// CONFIGURATION (define before including)
//   SSS_EXTRA_TARGETS  0 (default) or 1, as in SssChain.glsl (whose fetch and
//                      packing this header uses).
//   DISK_SSS_ROTATE    1 (default): the per-pixel rotation of SAMPLES; 0: every
//                      pixel samples the same spiral (the error then shows as
//                      structured copies of edges instead of noise; for
//                      inspection).
#ifndef DERMIS_DISK_SSS_GLSL
#define DERMIS_DISK_SSS_GLSL

#include "SssChain.glsl"
#include "SssEdges.glsl"

#ifndef DISK_SSS_ROTATE
#define DISK_SSS_ROTATE 1
#endif
#if DISK_SSS_ROTATE != 0 && DISK_SSS_ROTATE != 1
#error "DISK_SSS_ROTATE must be 0 or 1"
#endif

// Under this largest sample radius (pixels) every sample rounds to the centre (SAMPLES, Skip).
const float kDiskSssSkipPx = 0.5;

// The diffused values at `pixel`: [0].rgb by the per-channel weights, [0].a
// and [1] by the scalar one. The centre when the pixel is not on this slot
// (the stencil keeps that from happening) or the disk is under the skip size.
SssValues diskSss(SSS_CHAIN_SAMPLER colour, usampler2D depthKey, ivec2 pixel) {
    ivec2 size = textureSize(colour, 0);
    SssValues centre;
    uint centreKey;
    float viewDepthM;
    if (!sssCentre(colour, depthKey, pixel, uDiskSss.edges.slot, centre, centreKey, viewDepthM)) return centre;
    float pxPerMm = 1e-3 * uFrame.pixelsPerMetreAtUnitDepth / viewDepthM;
    if (uDiskSss.largestRadiusMm * pxPerMm < kDiskSssSkipPx) return centre;
    // Per screen axis, over the skin's stretch along it (SssChain.glsl, SLANT).
    SssSlant slantX = sssSlant(depthKey, pixel, ivec2(1, 0), centreKey, viewDepthM);
    SssSlant slantY = sssSlant(depthKey, pixel, ivec2(0, 1), centreKey, viewDepthM);
    vec2 pxPerMmOnSkin = pxPerMm / vec2(slantX.stretch, slantY.stretch);
    vec2 depthPerPxM = vec2(slantX.depthPerPxM, slantY.depthPerPxM);
    // The fill's slope test on the steeper axis: the disk's taps go every way.
    SssRejected rejected = sssRejected(centre, pixel, max(sssSlope(slantX), sssSlope(slantY)));

#if DISK_SSS_ROTATE
    float angle = 6.28318530718 * hashToUnit(uvec2(pixel));
#else
    float angle = 0.0;
#endif
    mat2 rotation = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    int samples = min(uDiskSss.sampleCount, DERMIS_MAX_DISK_SAMPLES);

    vec3 colourSum = vec3(0.0);
    vec3 colourWeightSum = vec3(0.0);
    SssValues scalarSum;
    for (int k = 0; k < SSS_VALUES; ++k) scalarSum.v[k] = vec4(0.0);
    float scalarWeightSum = 0.0;
    for (int j = 0; j < samples; ++j) {
        vec4 sampleMm = uDiskSss.samples[j];
        vec3 weight = uDiskSss.weights[j].rgb;
        float scalarWeight = sampleMm.w;
        ivec2 offsetPx = ivec2(floor(rotation * sampleMm.xy * pxPerMmOnSkin + 0.5));
        ivec2 tapPixel = clamp(pixel + offsetPx, ivec2(0), size - 1);
        SssEdgeTap edge = sssEdgeTap(centreKey, texelFetch(depthKey, tapPixel, 0).r, dot(vec2(offsetPx), depthPerPxM),
                                     uDiskSss.edges);
        if (edge.weight <= 0.0) continue;
        weight *= edge.weight;
        scalarWeight *= edge.weight;
        SssValues toward = sssRejectedFor(rejected, edge);
        SssValues tap = toward;
        if (edge.toCentre < 1.0) {
            tap = sssFetch(colour, tapPixel);
            for (int k = 0; k < SSS_VALUES; ++k) tap.v[k] = mix(tap.v[k], toward.v[k], edge.toCentre);
        }
        colourSum += weight * tap.v[0].rgb;
        colourWeightSum += weight;
        for (int k = 0; k < SSS_VALUES; ++k) scalarSum.v[k] += scalarWeight * tap.v[k];
        scalarWeightSum += scalarWeight;
    }
    if (!(scalarWeightSum > 0.0) || any(lessThanEqual(colourWeightSum, vec3(0.0)))) return centre;
    SssValues result;
    for (int k = 0; k < SSS_VALUES; ++k) result.v[k] = scalarSum.v[k] / scalarWeightSum;
    result.v[0].rgb = colourSum / colourWeightSum;
    return result;
}

#endif
