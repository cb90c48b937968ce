#include "mesh/SurfaceDistance.h"

#include "mesh/UvBake.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dermis {

glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + ab * (d1 / (d1 - d3));
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + ac * (d2 / (d2 - d6));
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const float denominator = 1.0f / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

TriangleDistance::TriangleDistance(const MeshData& mesh, const std::vector<uint32_t>& indices) : mMesh(mesh), mIndices(indices) {
    const size_t triangles = indices.size() / 3;
    if (triangles == 0) return;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t i : indices) {
        lo = glm::min(lo, mesh.vertices[i].position);
        hi = glm::max(hi, mesh.vertices[i].position);
    }
    const glm::vec3 size = glm::max(hi - lo, glm::vec3(1e-6f));
    // Cells about twice a triangle's size: a surface's triangles fill few cells of
    // its bounds, so a count from the volume would make cells far too coarse.
    double area = 0.0;
    for (size_t t = 0; t < triangles; ++t) {
        const glm::vec3& a = mesh.vertices[indices[3 * t]].position;
        area += 0.5 * double(glm::length(glm::cross(mesh.vertices[indices[3 * t + 1]].position - a,
                                                    mesh.vertices[indices[3 * t + 2]].position - a)));
    }
    const float extent = std::max(size.x, std::max(size.y, size.z));
    mCell = std::max(2.0f * float(std::sqrt(area / double(triangles))), extent / 256.0f);
    mCells = glm::clamp(glm::ivec3(glm::ceil(size / mCell)), glm::ivec3(1), glm::ivec3(256));
    mCell = std::max(size.x / float(mCells.x), std::max(size.y / float(mCells.y), size.z / float(mCells.z)));
    mOrigin = lo;
    const size_t cellCount = size_t(mCells.x) * size_t(mCells.y) * size_t(mCells.z);
    std::vector<uint32_t> counts(cellCount + 1, 0);
    const auto forEachCell = [&](size_t t, auto&& body) {
        const glm::vec3& a = mesh.vertices[indices[3 * t]].position;
        const glm::vec3& b = mesh.vertices[indices[3 * t + 1]].position;
        const glm::vec3& c = mesh.vertices[indices[3 * t + 2]].position;
        const glm::ivec3 from = cellOf(glm::min(a, glm::min(b, c)));
        const glm::ivec3 to = cellOf(glm::max(a, glm::max(b, c)));
        for (int z = from.z; z <= to.z; ++z)
            for (int y = from.y; y <= to.y; ++y)
                for (int x = from.x; x <= to.x; ++x) body((size_t(z) * size_t(mCells.y) + size_t(y)) * size_t(mCells.x) + size_t(x));
    };
    for (size_t t = 0; t < triangles; ++t) forEachCell(t, [&](size_t cell) { ++counts[cell + 1]; });
    for (size_t i = 1; i < counts.size(); ++i) counts[i] += counts[i - 1];
    mCellStart = counts;
    mCellTriangles.resize(counts.back());
    for (size_t t = 0; t < triangles; ++t) forEachCell(t, [&](size_t cell) { mCellTriangles[counts[cell]++] = uint32_t(t); });
}

glm::ivec3 TriangleDistance::cellOf(const glm::vec3& p) const {
    return glm::clamp(glm::ivec3(glm::floor((p - mOrigin) / mCell)), glm::ivec3(0), mCells - 1);
}

float TriangleDistance::distance(const glm::vec3& p, float limit) const {
    float best = limit;
    if (mCellStart.empty()) return best;
    const glm::ivec3 centre = cellOf(p);
    const int rings = std::max(mCells.x, std::max(mCells.y, mCells.z));
    for (int r = 0; r <= rings; ++r) {
        // Triangles only in cells r or more steps away lie at least (r - 1) cells from p.
        if (r >= 1 && best <= float(r - 1) * mCell) break;
        const glm::ivec3 from = glm::max(centre - r, glm::ivec3(0));
        const glm::ivec3 to = glm::min(centre + r, mCells - 1);
        for (int z = from.z; z <= to.z; ++z) {
            for (int y = from.y; y <= to.y; ++y) {
                for (int x = from.x; x <= to.x; ++x) {
                    const glm::ivec3 offset = glm::abs(glm::ivec3(x, y, z) - centre);
                    if (std::max(offset.x, std::max(offset.y, offset.z)) != r) continue;  // the shell only
                    // A cell no nearer than the best so far holds nothing better.
                    const glm::vec3 cellLo = mOrigin + glm::vec3(x, y, z) * mCell;
                    const glm::vec3 outside = glm::max(glm::max(cellLo - p, p - (cellLo + mCell)), glm::vec3(0.0f));
                    if (glm::dot(outside, outside) >= best * best) continue;
                    const size_t cell = (size_t(z) * size_t(mCells.y) + size_t(y)) * size_t(mCells.x) + size_t(x);
                    for (uint32_t k = mCellStart[cell]; k < mCellStart[cell + 1]; ++k) {
                        const size_t t = mCellTriangles[k];
                        const glm::vec3 q = closestPointOnTriangle(p, mMesh.vertices[mIndices[3 * t]].position,
                                                                   mMesh.vertices[mIndices[3 * t + 1]].position,
                                                                   mMesh.vertices[mIndices[3 * t + 2]].position);
                        best = std::min(best, glm::length(p - q));
                    }
                }
            }
        }
    }
    return best;
}

namespace {

// The largest distance from `from`'s sample points to `to`'s surface.
float oneSided(const MeshData& mesh, const std::vector<uint32_t>& from, const std::vector<uint32_t>& to, int steps, float limit) {
    const TriangleDistance target(mesh, to);
    const size_t triangles = from.size() / 3;
    constexpr int kChunk = 256;
    const int chunks = int((triangles + kChunk - 1) / kChunk);
    std::vector<float> worst(size_t(chunks), 0.0f);
    forEachRow(chunks, [&](int chunk) {
        float w = 0.0f;
        for (size_t t = size_t(chunk) * kChunk; t < std::min(triangles, size_t(chunk + 1) * kChunk); ++t) {
            const glm::vec3& a = mesh.vertices[from[3 * t]].position;
            const glm::vec3& b = mesh.vertices[from[3 * t + 1]].position;
            const glm::vec3& c = mesh.vertices[from[3 * t + 2]].position;
            for (int i = 0; i <= steps; ++i)
                for (int j = 0; i + j <= steps; ++j) {
                    const float u = float(i) / float(steps), v = float(j) / float(steps);
                    w = std::max(w, target.distance(a + u * (b - a) + v * (c - a), limit));
                }
        }
        worst[size_t(chunk)] = w;
    });
    return worst.empty() ? 0.0f : *std::max_element(worst.begin(), worst.end());
}

}  // namespace

float sampledHausdorffDistance(const MeshData& mesh, const std::vector<uint32_t>& first, const std::vector<uint32_t>& second,
                               int steps, float limit) {
    return std::max(oneSided(mesh, first, second, steps, limit), oneSided(mesh, second, first, steps, limit));
}

}  // namespace dermis
