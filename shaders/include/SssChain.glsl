// SssChain.glsl: what every screen-space SSS technique's step shares: the
// chain it reads (plain colour, or colour and the LEAN moments packed), its
// centre pixel, its packing and sanitising. The techniques' own steps are in
// SssBlur.glsl (d'Eon & Luebke's Gaussian chain), SeparableSss.glsl
// (Jimenez's separable pair) and DiskSss.glsl (the disk); the edge rules in
// SssEdges.glsl. This header is its own manual.
//
// EXTRA TARGETS AND ALPHA (the LEAN moments, include/Lean.glsl)
//   The colour's alpha (1, or in the LEAN variants the cross moment M'.xy)
//   and every extra target (B'.x, B'.y, M'.xx, M'.yy) are blurred with the
//   very taps and weights of the colour, in the same draw (Vila Verde 2015 blurred four textures in four passes,
//   about 4x the cost of the control blur; here the taps' depth keys and
//   weights are computed once). Their accumulation weight per Gaussian is one
//   scalar (alpha and extra targets alike), the mean of the Gaussian's RGB
//   weights (engine/plan/SssVariant.h),
//   because:
//   - the profile's weights are normalised per channel, so the means also
//     sum to one with the identity weight: the accumulated moments are a
//     convex combination of moments, i.e. the moments of a mixture, whose
//     covariance M - B B^T is positive semi-definite (a per-channel or
//     per-target weight would not be: B and M must come from one mixture);
//   - every step above is itself convex (bilateral and control: a lerp
//     towards the centre, weights divided by their sum), so nothing leaves
//     that set;
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
// SLANT (every technique)
//   A profile's width is a distance on the skin. A pixel step at view depth z
//   covers z / P metres of the view plane (P = uFrame.pixelsPerMetreAtUnitDepth),
//   but on skin that slopes away from the view by g metres of depth per metre
//   it covers sqrt(1 + g^2) times that. Each technique therefore divides its
//   width in pixels along a screen axis by the skin's stretch on that axis
//   (sssSlant); without it a slanted cheek or the side of the nose is blurred
//   over too much skin, by 1 / cos of the slant (docs/screen-space.md, "Width
//   on slanted skin"). g comes from the depth keys of the two neighbours on
//   the axis, the flatter of the two, so that a crease or a silhouette next
//   to the pixel does not count; a pixel without such a neighbour keeps its
//   width.
//   The edge test (SssEdges.glsl) then measures a tap's depth against the
//   centre's plane, not against its depth: on a slope the taps lie deeper or
//   shallower by depthPerPxM per pixel without crossing an edge, and the
//   bilateral's 1 mm against the centre's depth cut the kernel there (on a
//   60-degree slope seen at 0.1 mm per pixel, to about 6 px).
//   From g = kSssMaxSlope (63 degrees) on, the width stops shrinking and the
//   edge test goes back to the centre's depth: so near an outline, where the
//   skin curves away within the kernel and its far side is out of view, the
//   kernel is trimmed towards the outline as before. On the head scan that
//   is worth 1.20% against 1.17% of scatter error (the shoulders' rim), with
//   g clamped at 4 and measured against the plane all the way.
//
// EDGES (include/SssEdges.glsl)
//   bilateral (the default of lbb), control (c, lcb) or fetch-only (the
//   benchmarks' bandwidth floor: the fetches of colour and key of every tap
//   on the same profile, summed with the kernel weights and nothing else).
//
// CONFIGURATION (define before including)
//   SSS_EXTRA_TARGETS  0 (default) or 1: one extra RGBA target (the LEAN
//                      moments) blurred with the same taps; the chain is then
//                      packed (PACKING above) and SSS_CHAIN_SAMPLER is a
//                      usampler2D.
//   SSS_PACKED_OUT     with SSS_EXTRA_TARGETS = 1 only: 1 (default) writes the
//                      packed chain, 0 writes the colour alone (WHERE THE
//                      MOMENTS STOP). Read by sss_blur.frag and sss_separable.frag.
#ifndef DERMIS_SSS_CHAIN_GLSL
#define DERMIS_SSS_CHAIN_GLSL

#include "SssEdges.glsl"
#include "ThinEdges.glsl"

layout(binding = DERMIS_UNIT_HIDDEN_SIDE) uniform sampler2D uHiddenSide;  // passes/ThinEdgePasses.cpp

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

const float kSssMaxSlope = 2.0;

// The skin along one screen axis at a pixel (SLANT).
struct SssSlant {
    float stretch;      // sqrt(1 + g^2): skin per view-plane distance
    float depthPerPxM;  // the view depth's change per pixel along the axis; 0 from kSssMaxSlope on
};

SssSlant sssSlant(usampler2D depthKey, ivec2 pixel, ivec2 step, uint centreKey, float viewDepthM) {
    ivec2 size = textureSize(depthKey, 0);
    SssSlant slant = SssSlant(1.0, 0.0);
    float flattestM = -1.0;
    for (int side = -1; side <= 1; side += 2) {
        uint key = texelFetch(depthKey, clamp(pixel + side * step, ivec2(0), size - 1), 0).r;
        if (slotFromKey(key) != slotFromKey(centreKey) || isBackgroundKey(key)) continue;
        float differenceM = viewDepthFromKey(key) - viewDepthM;
        if (flattestM >= 0.0 && abs(differenceM) >= flattestM) continue;
        flattestM = abs(differenceM);
        slant.depthPerPxM = float(side) * differenceM;
    }
    if (flattestM < 0.0) return slant;
    float metresPerPx = viewDepthM / uFrame.pixelsPerMetreAtUnitDepth;
    float slope = min(flattestM / metresPerPx, kSssMaxSlope);
    slant.stretch = sqrt(1.0 + slope * slope);
    slant.depthPerPxM = slope >= kSssMaxSlope ? 0.0 : sign(slant.depthPerPxM) * slope * metresPerPx;
    return slant;
}

// The skin's slope along the axis (g of SLANT, at most kSssMaxSlope).
float sssSlope(SssSlant slant) { return sqrt(max(slant.stretch * slant.stretch - 1.0, 0.0)); }

// What a tap's rejected share takes (SssEdges.glsl): the centre's values, or
// past the outline of a thin part the fill of include/ThinEdges.glsl, for the
// colour only (the LEAN moments of the hidden side are not known; they stay the
// centre's). `slope`: the centre's along the tap's axis.
struct SssRejected {
    SssValues centre;
    SssValues outside;
};

SssRejected sssRejected(SssValues centre, ivec2 pixel, float slope) {
    SssRejected rejected = SssRejected(centre, centre);
    vec4 hiddenSide = hiddenSideAt(uHiddenSide, pixel);
    float weight = thinEdgeWeight(hiddenSide, slope);
    if (weight > 0.0) rejected.outside.v[0].rgb = thinEdgeFill(centre.v[0].rgb, hiddenSide, weight);
    return rejected;
}

SssValues sssRejectedFor(SssRejected rejected, SssEdgeTap edge) { return edge.outside ? rejected.outside : rejected.centre; }

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

// Keeps a signed value (a LEAN moment) storable in fp16 and free of NaN, so
// one bad texel cannot spread through the chain.
vec4 sssSanitizeSigned(vec4 value) {
    return sanitiseRange(value, -kHalfMax, kHalfMax);
}

#endif
