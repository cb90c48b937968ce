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

// The level's error is the simplifier's estimate (the square root of its
// quadric error) times this: on a unit sphere the true deviation, less the full
// mesh's own, reached 1.81x the estimate (tests/unit/test_level_of_detail.cpp).
constexpr float kLodErrorMargin = 2.0f;

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
