#include "reference/SurfaceCells.h"

#include <algorithm>
#include <cmath>

namespace dermis::reference {
namespace {

// Grids larger than this (in grid cells) get coarser cells instead.
constexpr size_t kMaxGridCells = size_t(1) << 22;

// Divisions per side of the triangle for cells of at most maxEdgeM; 0 for a zero-area triangle.
int divisions(const CharacterSurface& surface, size_t t, float maxEdgeM) {
    const glm::vec3 p0 = surface.corner(t, 0), p1 = surface.corner(t, 1), p2 = surface.corner(t, 2);
    if (!(glm::length(glm::cross(p1 - p0, p2 - p0)) > 0.0f)) return 0;
    const float longest = std::max({glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    return static_cast<int>(std::clamp(std::ceil(longest / std::max(maxEdgeM, 1e-9f)), 1.0f, float(kMaxBaseDivisions)));
}

}  // namespace

glm::vec2 cellCentroid(const Cell& cell) { return (cell.corners[0] + cell.corners[1] + cell.corners[2]) / 3.0f; }

CellShape cellShape(const CharacterSurface& surface, const Cell& cell) {
    std::array<glm::vec3, 3> p;
    for (int i = 0; i < 3; ++i) p[size_t(i)] = surface.positionAt(cell.triangle, cell.corners[size_t(i)].x, cell.corners[size_t(i)].y);
    CellShape shape;
    shape.centroidM = (p[0] + p[1] + p[2]) / 3.0f;
    for (int i = 0; i < 3; ++i) {
        shape.boundRadiusM = std::max(shape.boundRadiusM, glm::length(p[size_t(i)] - shape.centroidM));
        shape.maxEdgeM = std::max(shape.maxEdgeM, glm::length(p[size_t((i + 1) % 3)] - p[size_t(i)]));
    }
    shape.areaM2 = 0.5f * glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    return shape;
}

std::array<Cell, 4> splitCell(const Cell& cell) {
    const glm::vec2& a = cell.corners[0];
    const glm::vec2& b = cell.corners[1];
    const glm::vec2& c = cell.corners[2];
    const glm::vec2 ab = 0.5f * (a + b);
    const glm::vec2 bc = 0.5f * (b + c);
    const glm::vec2 ca = 0.5f * (c + a);
    const uint32_t t = cell.triangle;
    return {Cell{t, {a, ab, ca}}, Cell{t, {ab, b, bc}}, Cell{t, {ca, bc, c}}, Cell{t, {bc, ca, ab}}};
}

size_t countTessellationCells(const CharacterSurface& surface, float maxEdgeM, const std::vector<uint8_t>* triangles) {
    size_t count = 0;
    for (size_t t = 0; t < surface.triangleCount(); ++t) {
        if (triangles && !(*triangles)[t]) continue;
        const auto n = size_t(divisions(surface, t, maxEdgeM));
        count += n * n;
    }
    return count;
}

std::vector<Cell> tessellate(const CharacterSurface& surface, float maxEdgeM, const std::vector<uint8_t>* triangles) {
    std::vector<Cell> cells;
    for (size_t t = 0; t < surface.triangleCount(); ++t) {
        if (triangles && !(*triangles)[t]) continue;
        const int n = divisions(surface, t, maxEdgeM);
        if (n == 0) continue;
        const float step = 1.0f / float(n);
        const auto triangle = static_cast<uint32_t>(t);
        // Lattice point (i, j) has weights (i / n, j / n); each lattice square gives an
        // "up" cell and, inside the triangle, a "down" one.
        for (int i = 0; i < n; ++i) {
            for (int j = 0; i + j < n; ++j) {
                const glm::vec2 q00(float(i) * step, float(j) * step);
                const glm::vec2 q10(float(i + 1) * step, float(j) * step);
                const glm::vec2 q01(float(i) * step, float(j + 1) * step);
                cells.push_back(Cell{triangle, {q00, q10, q01}});
                if (i + j + 1 < n) {
                    const glm::vec2 q11(float(i + 1) * step, float(j + 1) * step);
                    cells.push_back(Cell{triangle, {q10, q11, q01}});
                }
            }
        }
    }
    return cells;
}

CellGrid::CellGrid(const std::vector<glm::vec3>& centroidsM, float cellSizeM) : mCentroidsM(centroidsM) {
    if (centroidsM.empty()) return;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& c : centroidsM) {
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    const glm::vec3 extent = hi - lo;
    mCellSizeM = std::max(cellSizeM, 1e-6f);
    for (;;) {
        mDims = glm::max(glm::ivec3(glm::floor(extent / mCellSizeM)) + 1, glm::ivec3(1));
        if (size_t(mDims.x) * size_t(mDims.y) * size_t(mDims.z) <= kMaxGridCells) break;
        mCellSizeM *= 1.5f;
    }
    mOriginM = lo;
    const size_t gridCells = size_t(mDims.x) * size_t(mDims.y) * size_t(mDims.z);
    std::vector<uint32_t> keys(centroidsM.size());
    mStart.assign(gridCells + 1, 0);
    for (size_t i = 0; i < centroidsM.size(); ++i) {
        const glm::ivec3 g = glm::clamp(glm::ivec3(glm::floor((centroidsM[i] - mOriginM) / mCellSizeM)), glm::ivec3(0), mDims - 1);
        keys[i] = static_cast<uint32_t>((size_t(g.z) * size_t(mDims.y) + size_t(g.y)) * size_t(mDims.x) + size_t(g.x));
        ++mStart[keys[i] + 1];
    }
    for (size_t g = 0; g < gridCells; ++g) mStart[g + 1] += mStart[g];
    mItems.resize(centroidsM.size());
    std::vector<uint32_t> fill(mStart.begin(), mStart.end() - 1);
    for (size_t i = 0; i < centroidsM.size(); ++i) mItems[fill[keys[i]]++] = static_cast<uint32_t>(i);
}

}  // namespace dermis::reference
