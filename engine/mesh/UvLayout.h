#pragma once
// What texture-space SSS needs to know about a mesh's UV layout, worked out
// once on the CPU from the mesh alone (no GL):
//
//  - per vertex, the derivatives of the position with respect to u and v, in
//    object units per UV unit. Their world-space lengths are the stretch map
//    (Chappuis 2011 §2.2.4 listing 2.1, Yang et al. 2012 §II): how far on the surface one
//    unit of u or v reaches, which sets the spacing of the blur taps.
//    Listing 2.1 takes dFdx(worldPosition) per fragment, which is constant
//    over each triangle; on the 64 x 32 UV sphere that is off by up to
//    dtheta cot(theta) (10% at 45 degrees latitude) and steps from triangle
//    to triangle. Averaged per vertex (weighted by UV area) and interpolated,
//    the error is second order instead.
//  - per vertex, the distance along the surface to the nearest UV chart
//    border (a seam or the mesh's edge), in object units. A texture-space blur
//    cannot see light from across a border, so near one the final gather
//    blends to local diffuse (docs/texture-space.md).
//  - per vertex, the UV across that border where the border is a seam (the
//    same surface point in another chart, or the other side of a cut), and
//    whether the surface turns round there: the gather reads the light
//    beyond the border there (shaders/ts_gather.frag).
//  - summary stretch figures from which the planner picks a texture size.
//
// Degenerate triangles (no area in UV, or none in space) add nothing, so every
// value is finite; a vertex with only degenerate triangles gets zero
// derivatives.

#include "mesh/Mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace dermis {

struct UvLayout {
    std::vector<glm::vec3> dPdu;        // per vertex, object units per unit of u
    std::vector<glm::vec3> dPdv;        // per vertex, object units per unit of v
    std::vector<float> borderDistance;  // per vertex, object units along mesh edges to a chart border
    // Per vertex, where the surface goes on across its nearest chart border
    // (its border node: the nearest by edge paths):
    //   xy  the UV, on the chart beyond, of that border point: the border
    //       vertex at the same position (the other side of a seam);
    //   z   1 where there is one, 0 where the border is the mesh's own edge,
    //       where the chart beyond ends within half of kSeamProbeM from it (a
    //       strip round a box's thin end: its light is not what lies beyond),
    //       or where no border is reached;
    //   w   how far the surface turns round across the seam: -N.N' for the
    //       normals kSeamProbeM into either chart from the border point (the
    //       nodes nearest to that distance among those whose nearest border
    //       node it is, or the farthest of them), 1 at the rim of a thin
    //       part (an ear's two faces), -1 where the surface goes on flat.
    std::vector<glm::vec4> seamContinuation;
    // Per vertex, 1 where it lies inside the body (an ear's root sunk into
    // the skull, the skull under it), where no light enters: the irradiance
    // texture leaves those texels empty, as the reference leaves that surface
    // out (docs/texture-space.md, "Surface inside the body"). Filled by
    // plan/SceneGeometry.cpp (env/ShTransfer.h findBuriedVertices), not by
    // analyseUvLayout; empty: none.
    std::vector<uint8_t> buried;
    // Median over vertices of sqrt(|dP/du| |dP/dv|): the typical object-space
    // length of one UV unit. 0 for a mesh without a usable triangle.
    float medianStretch = 0.0f;
    // The 10th percentile of the same: the dense parts of the layout (a
    // lower percentile, or min(|dP/du|, |dP/dv|), would be ruled by the
    // singular points of a layout such as a sphere's poles).
    float denseStretch = 0.0f;
    // The share of the surface (spatial area; triangles degenerate in space
    // left out) on triangles with no area in UV: a mesh without TEXCOORD_0
    // (every UV 0) has 1, a usable layout 0. An irradiance texture cannot
    // hold light for such triangles (plan/TsPlan.h falls back).
    float uvlessSurfaceFraction = 0.0f;
    // The share of the texels of the unit UV square that the layout covers
    // which more than one triangle covers (texel centres of a
    // kUvOverlapGrid^2 grid; UVs outside [0, 1] cover nothing, as the
    // irradiance texture clips them): mirrored or stacked charts share texels,
    // and an irradiance texture can hold only one light per texel.
    float uvOverlapFraction = 0.0f;
    // The share of the unit UV square's texels (the same grid) that the
    // layout covers: near 1 for a layout that fills the square, small for an
    // atlas with much empty space, whose irradiance texture is mostly unused.
    float uvCoverageFraction = 0.0f;
};

// The grid uvOverlapFraction is counted on.
constexpr int kUvOverlapGrid = 512;

// A border vertex that no edge path reaches keeps this distance.
constexpr float kFarFromBorder = 1e6f;

// How far into the charts the seam's turn is measured (seamContinuation.w):
// the widest skin Gaussian's reach, about its standard deviation (2.7 mm in
// d'Eon & Luebke 2007's fit), beyond the rolled rim of an ear.
constexpr float kSeamProbeM = 0.003f;

// `metresPerUnit`: the mesh's scale in the world, for kSeamProbeM.
UvLayout analyseUvLayout(const MeshData& mesh, float metresPerUnit);

// Only the per-vertex derivatives (and uvlessSurfaceFraction): what GPU
// skinning transforms each frame for an animated character's stretch map
// (shaders/skinning.comp), from its bind pose.
UvLayout analyseUvDerivatives(const MeshData& mesh);

}  // namespace dermis
