#pragma once
// The distance from points to a set of triangles, through a uniform grid of
// the triangles' bounds: used to measure how far a level of detail lies from
// the full mesh (mesh/MeshLod.h) instead of trusting the simplifier's estimate.

#include "mesh/Mesh.h"

#include <cstdint>
#include <vector>

namespace dermis {

class TriangleDistance {
public:
    // The triangles `indices` (a triangle list) over mesh's vertices.
    TriangleDistance(const MeshData& mesh, const std::vector<uint32_t>& indices);

    // The distance from p to the nearest triangle, or `limit` where none is nearer
    // (the search ends there, so a far point costs no more than a near one).
    float distance(const glm::vec3& p, float limit) const;

private:
    const MeshData& mMesh;
    const std::vector<uint32_t>& mIndices;
    glm::vec3 mOrigin{0.0f};
    float mCell = 1.0f;
    glm::ivec3 mCells{0};
    std::vector<uint32_t> mCellStart;  // per cell, into mCellTriangles; one more entry than cells
    std::vector<uint32_t> mCellTriangles;

    glm::ivec3 cellOf(const glm::vec3& p) const;
};

// The closest point to p on the triangle (a, b, c) (Ericson, "Real-Time
// Collision Detection", 2005, §5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// The larger of the two one-sided distances between the triangle lists
// `first` and `second` over mesh's vertices, sampled: each list's vertices
// and a barycentric grid of `steps` per edge on each of its triangles,
// measured against the other list's surface (a sampled Hausdorff distance);
// at most `limit`.
float sampledHausdorffDistance(const MeshData& mesh, const std::vector<uint32_t>& first, const std::vector<uint32_t>& second,
                               int steps, float limit);

}  // namespace dermis
