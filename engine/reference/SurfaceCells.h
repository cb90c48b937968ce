#pragma once
// The reference's tessellation: cells are small triangles inside one mesh
// triangle, given by their corners' barycentric weights, so that any point of a
// cell can be shaded exactly like the mesh (normals, UVs, maps) and the cells
// tile the surface without gaps or overlaps. A base tessellation divides every
// mesh triangle uniformly; the integrator splits cells further (4-way, at edge
// midpoints) where a narrow Gaussian needs them finer.

#include "reference/CharacterSurface.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace dermis::reference {

struct Cell {
    uint32_t triangle = 0;
    std::array<glm::vec2, 3> corners{};  // (b1, b2): weights of the mesh triangle's second and third corners
};

struct CellShape {
    glm::vec3 centroidM{0.0f};
    float boundRadiusM = 0.0f;  // every point of the cell lies within this of the centroid
    float maxEdgeM = 0.0f;
    float areaM2 = 0.0f;
};

CellShape cellShape(const CharacterSurface& surface, const Cell& cell);
glm::vec2 cellCentroid(const Cell& cell);

// The four halves-of-edges children; the last is the middle one, whose centroid
// is the parent's.
std::array<Cell, 4> splitCell(const Cell& cell);

// Every mesh triangle divided into n^2 congruent cells, n the smallest with every
// cell edge <= maxEdgeM (n capped at kMaxBaseDivisions). Zero-area triangles give no cells.
// `triangles` (one flag per triangle; null: all) keeps the triangles flagged:
// the diffusion group of one profile (ReferenceRenderer.h).
constexpr int kMaxBaseDivisions = 4096;
std::vector<Cell> tessellate(const CharacterSurface& surface, float maxEdgeM,
                             const std::vector<uint8_t>* triangles = nullptr);
// The number of cells tessellate() would make, without making them.
size_t countTessellationCells(const CharacterSurface& surface, float maxEdgeM,
                              const std::vector<uint8_t>* triangles = nullptr);

// A uniform grid over cell centroids for "cells near this point" queries.
class CellGrid {
public:
    CellGrid() = default;
    CellGrid(const std::vector<glm::vec3>& centroidsM, float cellSizeM);

    // Calls visit(index) for every centroid within radiusM of pointM, in index
    // order within each grid cell, grid cells in a fixed order.
    template <class Visit>
    void forEachNear(const glm::vec3& pointM, float radiusM, Visit&& visit) const;

private:
    glm::vec3 mOriginM{0.0f};
    float mCellSizeM = 1.0f;
    glm::ivec3 mDims{0};
    std::vector<uint32_t> mStart;  // per grid cell, into mItems; size = cells + 1
    std::vector<uint32_t> mItems;
    std::vector<glm::vec3> mCentroidsM;
};

template <class Visit>
void CellGrid::forEachNear(const glm::vec3& pointM, float radiusM, Visit&& visit) const {
    if (mItems.empty()) return;
    const glm::ivec3 lo = glm::clamp(glm::ivec3(glm::floor((pointM - radiusM - mOriginM) / mCellSizeM)), glm::ivec3(0),
                                     mDims - 1);
    const glm::ivec3 hi = glm::clamp(glm::ivec3(glm::floor((pointM + radiusM - mOriginM) / mCellSizeM)), glm::ivec3(0),
                                     mDims - 1);
    const float radiusSquared = radiusM * radiusM;
    for (int z = lo.z; z <= hi.z; ++z) {
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x) {
                const size_t g = (size_t(z) * size_t(mDims.y) + size_t(y)) * size_t(mDims.x) + size_t(x);
                for (uint32_t i = mStart[g]; i < mStart[g + 1]; ++i) {
                    const uint32_t item = mItems[i];
                    const glm::vec3 d = mCentroidsM[item] - pointM;
                    if (glm::dot(d, d) <= radiusSquared) visit(item);
                }
            }
        }
    }
}

}  // namespace dermis::reference
