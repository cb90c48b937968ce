// SssEdges.glsl: how one tap of a screen-space SSS kernel counts at a depth
// edge, shared by every screen-space technique (the d'Eon chain in
// SssBlur.glsl, Separable SSS, the disk) so that they stop light at the same
// silhouettes.
//
// Taps read the depth key (profile slot + view depth, UniformBlocks.glsl), so
// one test rejects taps across silhouettes, on the background, on opaque
// objects and on other profiles:
//   - bilateral (Vila Verde 2015 §4.3.2): the tap counts by
//     b = exp(-d^2 / (2 s^2)), d = the tap's depth difference in mm from the
//     centre's plane (SssChain.glsl, SLANT), s = bilateralDepthMm. A tap on
//     another profile or the background has b = 0. No light crosses an edge:
//     no halo, no background bleed. The share 1 - b of the tap's kernel
//     weight goes to the centre's value (toCentre = 1 - b), not to the other
//     taps: the skin behind an edge (beyond an outline, under the nose, under
//     an occluder) is out of view and taken to go on as it is at the centre.
//     Renormalising by the kept weights instead takes it to be like the
//     visible taps, which lie on the far side of the centre: beside an
//     occluder it pulled lit skin towards the dark side
//     (SssEdge.SkinHiddenBehindAnOccluderKeepsTheLightOfItsSide: 0.20%
//     against 0.92% of the step). Scatter error against the matched
//     reference at 640x360: default head 1.30% against 1.34%, head scan
//     0.95% against 1.01% (docs/screen-space.md, "Skin out of view").
//   - control (Jimenez et al. 2009, Vila Verde 2015 §3.2.2): the tap's value
//     is lerped back to the centre's by min(1, k d), k = controlScalePerMm;
//     its weight stays. A tap on another profile is the centre.
//   - fetch-only: weight 1, no lerp, on the same profile (a benchmark floor,
//     not a blur); a tap on another profile or the background is dropped as
//     bilateral drops it: the chain holds no value of this frame there (the
//     SSS init writes only the profiles' pixels, and a pooled target keeps
//     what it held), which stress seed 1835 read as light from nowhere.
// Past the outline of a thin part (`outside`, a centre facing the view, a
// short path through the part) the rejected share takes the thin-edge fill
// in place of the centre (include/ThinEdges.glsl; sssRejected in SssChain.glsl).
// A tap whose toCentre is 1 must not be fetched at all (selection, not a
// multiply), so a non-finite value outside the mask can never leak in. The
// caller divides by the sum of the weights it used (all 1 but fetch-only's).
#ifndef DERMIS_SSS_EDGES_GLSL
#define DERMIS_SSS_EDGES_GLSL

#include "Common.glsl"

struct SssEdgeTap {
    float weight;    // multiplies the kernel's weight (0: drop the tap)
    float toCentre;  // the tap's value is mix(tap, centre, toCentre)
    bool outside;    // past the centre's outline (include/ThinEdges.glsl)
};

// `planeOffsetM`: how much deeper than the centre the tap lies on the centre's
// plane (the skin's slope times the tap's offset, SssChain.glsl SLANT); the
// depth difference d is the tap's depth against that.
SssEdgeTap sssEdgeTap(uint centreKey, uint tapKey, float planeOffsetM, SssEdgeParams params) {
    int edges = params.mode;
    float bilateralDepthMm = params.bilateralDepthMm;
    float controlScalePerMm = params.controlScalePerMm;
    SssEdgeTap result = SssEdgeTap(1.0, 0.0, false);
    bool sameProfile = keyDistanceMm(centreKey, tapKey) < DERMIS_OTHER_PROFILE_DISTANCE_MM * 0.5;
    float behindMm = (viewDepthFromKey(tapKey) - viewDepthFromKey(centreKey) - planeOffsetM) * 1000.0;
    float distanceMm = abs(behindMm);
    // Past the outline: the background, another profile behind, or this profile a clear step behind (where the
    // bilateral weight is 1%: the ear's rim seen against the head).
    result.outside = sameProfile ? behindMm > 3.0 * bilateralDepthMm
                                 : isBackgroundKey(tapKey) || viewDepthFromKey(tapKey) > viewDepthFromKey(centreKey);
    if (edges == DERMIS_BLUR_EDGES_FETCH_ONLY) {
        result.weight = sameProfile ? 1.0 : 0.0;
    } else if (edges == DERMIS_BLUR_EDGES_BILATERAL) {
        result.toCentre = sameProfile ? 1.0 - exp(-distanceMm * distanceMm / (2.0 * bilateralDepthMm * bilateralDepthMm)) : 1.0;
    } else {
        result.toCentre = sameProfile ? min(controlScalePerMm * distanceMm, 1.0) : 1.0;
    }
    return result;
}

#endif
