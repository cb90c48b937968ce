// ThinEdges.glsl: the light past the outline of a thin part (the rim of an
// ear, a nostril wing), shared by every screen-space technique (SssBlur.glsl,
// SeparableSss.glsl, DiskSss.glsl) and by the texture-space gather
// (ts_gather.frag). This header is its own manual; the measurements are in
// docs/screen-space.md, "Thin edges".
//
// THE PROBLEM
//   A kernel tap that lands past the character's outline takes the centre's
//   value (SssEdges.glsl): the skin out of view is taken to go on as it is
//   at the centre. That holds where a thick body curves away. At the rim of
//   a part a few millimetres thick seen face on, the skin past the outline
//   turns round the rim to the part's other side, a few millimetres away
//   through it, whose light is not the centre's: dark behind a front-lit ear
//   (which the reference's scattering then loses light to), lit behind a
//   back-lit one.
//
// THE PASS (shaders/thin_edges.frag, passes/ThinEdgePasses.cpp)
//   The back faces of the visible characters whose pixels read the fill (a
//   technique that blurs, or texture space) are drawn into a depth buffer and
//   a normal target of their own: the nearest back face behind each pixel,
//   the exit of the view ray from the part. Then, per SSS pixel, one RGBA16F
//   texel:
//   - rgb: the hidden side's own light times albedo^mix (as the irradiance
//     the blurs read): the ambient and the environment's diffuse light with
//     the normal turned round (-N), plus every light's radiance times
//     saturate(-N.L), each shadowed light only where its shadow map sees the
//     back point (the exit point) as the surface nearest it;
//   - a: the weight w of the fill below, 1 where the view ray's path through
//     the part (back depth - front depth) is under THIN_EDGE_FULL_MM and 0
//     over THIN_EDGE_NONE_MM, smooth between (so that a part growing thicker
//     in an animation does not pop); times 0 where the back face's normal
//     does not face away from the front's (-N.N_back under
//     THIN_EDGE_OPPOSED_NONE, full from THIN_EDGE_OPPOSED_FULL): a slanted
//     view ray leaves a thick body's corner through its side wall after a
//     short path too (the wedge of content/scenes/slab.json, 20 mm thick,
//     took the fill along its whole outline without this test).
//   Where the pass does not run (transmittance.thin_edges or SSS off, no SSS pixel)
//   the readers sample a 1x1 black texture instead: w = 0 everywhere, and
//   every tap behaves as before.
//
// THE FILL (thinEdgeFill)
//   A tap that falls past the centre's outline (the background, another
//   profile or character behind, or this profile more than three bilateral
//   widths behind: an ear seen against the head; not an occluder in front)
//   takes, for its rejected share (SssEdges.glsl toCentre),
//       mix(centre, THIN_EDGE_RIM_SHARE centre + THIN_EDGE_BACK_SHARE hidden, w)
//   instead of the centre, where the centre faces the view (its slope along
//   the tap's axis under THIN_EDGE_MAX_SLOPE: an outline pixel of a thick
//   body is steep, and its view ray's path is short there too).
//   - THIN_EDGE_RIM_SHARE = 1/pi: what a normal turning half-way round from
//     N to -N receives on average from a light in front of it (the mean of
//     max(cos phi, 0) over phi in [0, pi]).
//   - THIN_EDGE_BACK_SHARE = 0.45 is fitted, not derived: the screen-space
//     scatter error of the procedural head (whose ear is such a part)
//     against the matched reference at 640x360 is least there (0.96%; 0.97%
//     at 0.4, 1.00% at 0.5, 1.53% at 0.7); more overshoots, because the
//     exit point straight behind the centre is lit where most of the far
//     side, further from the rim, lies in the head's shadow.
//   - The head scan's ear is a rolled helix whose outline pixels pass the
//     slope test but whose path through the roll is longer: the path test
//     keeps the fill off it (0.88% with it, 0.99% without).
//   - Texture space (ts_gather.frag) adds, per Gaussian, its 1-D tail beyond
//     the nearest chart border times (fill - local light). Where that border
//     is a seam round a rim (mesh/UvLayout.h: the surface turns round across
//     it, THIN_EDGE_OPPOSED_* on -N.N' measured 3 mm into either chart), the
//     hidden side's light is the blurred texture's own, read across the seam
//     (thinEdgeRim with it): the ear's two faces are charts that meet at the
//     rim. 0.45 is least there too (the default head 1.11%; 0.3: 1.15%, 0.6:
//     1.15%).
#ifndef DERMIS_THIN_EDGES_GLSL
#define DERMIS_THIN_EDGES_GLSL

#include "Common.glsl"

#define THIN_EDGE_FULL_MM 4.0
#define THIN_EDGE_NONE_MM 8.0
#define THIN_EDGE_OPPOSED_NONE 0.1
#define THIN_EDGE_OPPOSED_FULL 0.4
#define THIN_EDGE_MAX_SLOPE 1.1
#define THIN_EDGE_RIM_SHARE 0.31830989
#define THIN_EDGE_BACK_SHARE 0.45

// The pass's texel at `pixel`; (0, 0, 0, 0) from the 1x1 stand-in.
vec4 hiddenSideAt(sampler2D hiddenSide, ivec2 pixel) {
    ivec2 size = textureSize(hiddenSide, 0);
    return size.x == 1 && size.y == 1 ? vec4(0.0) : texelFetch(hiddenSide, pixel, 0);
}

// The fill's weight at a centre: w where its slope along the tap's axis is
// under THIN_EDGE_MAX_SLOPE, else 0. `slope`: |d view depth| / d view-plane
// distance.
float thinEdgeWeight(vec4 hiddenSide, float slope) {
    return slope < THIN_EDGE_MAX_SLOPE ? hiddenSide.a : 0.0;
}

// How much a part's far side faces away from its near side, from -N.N_far:
// 0 under THIN_EDGE_OPPOSED_NONE, 1 from THIN_EDGE_OPPOSED_FULL.
float thinEdgeOpposed(float minusNDotNFar) {
    return smoothstep(THIN_EDGE_OPPOSED_NONE, THIN_EDGE_OPPOSED_FULL, minusNDotNFar);
}

// The light past the rim of a thin part: the centre's share round the rim
// plus the hidden side's.
vec3 thinEdgeRim(vec3 centre, vec3 hidden) { return THIN_EDGE_RIM_SHARE * centre + THIN_EDGE_BACK_SHARE * hidden; }

// What a tap past the outline takes for its rejected share, given the
// centre's value and the weight above.
vec3 thinEdgeFill(vec3 centre, vec4 hiddenSide, float weight) {
    return mix(centre, thinEdgeRim(centre, hiddenSide.rgb), weight);
}

#endif
