#pragma once
// Levels of detail: coarser triangle lists over a model's own vertices, made
// with meshoptimizer's simplifier (edge collapses ordered by Garland &
// Heckbert's quadric error metric, "Surface Simplification Using Quadric
// Error Metrics", 1997). The vertices are shared with the full mesh, so
// skinning, morph targets, the SH transfer and the UVs carry over unchanged.
// Each draw range (submesh) is simplified on its own with its border locked,
// so neighbouring submeshes stay sealed; UV seams are kept by the simplifier.

#include "mesh/Model.h"

#include <vector>

namespace dermis {

// A level's error is measured: the sampled Hausdorff distance between its
// surface and the full mesh's (mesh/SurfaceDistance.h), on a barycentric grid
// of this many steps per edge on every triangle of each (3 takes the centroid).
// The simplifier's own estimate is a quadric error, the distance to the planes
// of the faces a vertex merged: a thin part (an ear's rim) folded onto itself
// stays on those planes, and on the procedural head the estimate said 0.45 px
// where the ear seen edge on lost whole pixels (docs/crowds.md).
constexpr int kLodErrorSamplesPerEdge = 3;

// Levels besides the full mesh, at most.
constexpr int kMaxLodLevels = 3;
// Each level aims at this share of the previous one's triangles.
constexpr float kLodTriangleRatio = 0.25f;
// Below this many triangles a mesh gets no levels: drawing it costs little.
constexpr size_t kMinLodTriangles = 2048;

// A level whose error exceeds this share of the mesh's extent is dropped: a
// character that small on screen is a few pixels, which the full mesh draws
// cheaply enough.
constexpr float kMaxLodRelativeError = 0.02f;

// The levels, finest first; fewer than kMaxLodLevels where the simplifier
// cannot remove a tenth of the previous level's triangles or its error
// exceeds kMaxLodRelativeError.
std::vector<LodLevel> makeLodLevels(const MeshData& mesh, const std::vector<Submesh>& ranges);

}  // namespace dermis
