#include "mesh/UvBake.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace dermis {
namespace {

float edge(const glm::vec2& a, const glm::vec2& b, const glm::vec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

glm::vec3 orthonormalTo(const glm::vec3& n, const glm::vec3& t) {
    const glm::vec3 projected = t - n * glm::dot(n, t);
    const float length = glm::length(projected);
    if (length > 1e-6f) return projected / length;
    const glm::vec3 axis = std::fabs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(axis - n * glm::dot(n, axis));
}

}  // namespace

namespace {

// Fills the texels of rows [rowBegin, rowEnd) that `triangle` covers.
void rasteriseTriangle(const MeshData& mesh, size_t triangle, uint8_t part, int rowBegin, int rowEnd, SurfaceMap& map) {
    const glm::vec2 scale(static_cast<float>(map.width), static_cast<float>(map.height));
    const Vertex* v[3];
    glm::vec2 p[3];
    for (int c = 0; c < 3; ++c) {
        v[c] = &mesh.vertices[mesh.indices[3 * triangle + static_cast<size_t>(c)]];
        p[c] = v[c]->uv * scale;
    }
    const float area = edge(p[0], p[1], p[2]);
    if (area == 0.0f || !std::isfinite(area)) return;
    // The surface's derivatives per texel step along x and y, from the
    // triangle's edges in UV and in space.
    const glm::vec2 d1 = p[1] - p[0];
    const glm::vec2 d2 = p[2] - p[0];
    const glm::vec3 e1 = v[1]->position - v[0]->position;
    const glm::vec3 e2 = v[2]->position - v[0]->position;
    const glm::vec3 perX = (e1 * d2.y - e2 * d1.y) / area;
    const glm::vec3 perY = (e2 * d1.x - e1 * d2.x) / area;
    const float footprint = std::max(glm::length(perX), glm::length(perY));
    const glm::vec2 lo = glm::min(p[0], glm::min(p[1], p[2]));
    const glm::vec2 hi = glm::max(p[0], glm::max(p[1], p[2]));
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
    const int y0 = std::max(rowBegin, static_cast<int>(std::floor(lo.y)));
    const int x1 = std::min(map.width - 1, static_cast<int>(std::ceil(hi.x)));
    const int y1 = std::min(rowEnd - 1, static_cast<int>(std::ceil(hi.y)));
    // Centres on an edge count as inside, so neighbours leave no cracks.
    const float tolerance = -1e-5f;
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            const float b0 = edge(p[1], p[2], centre) / area;
            const float b1 = edge(p[2], p[0], centre) / area;
            const float b2 = 1.0f - b0 - b1;
            if (b0 < tolerance || b1 < tolerance || b2 < tolerance) continue;
            SurfaceTexel& texel = map.texels[static_cast<size_t>(y) * static_cast<size_t>(map.width) + static_cast<size_t>(x)];
            texel.position = b0 * v[0]->position + b1 * v[1]->position + b2 * v[2]->position;
            texel.normal = glm::normalize(b0 * v[0]->normal + b1 * v[1]->normal + b2 * v[2]->normal);
            const glm::vec3 tangent =
                b0 * glm::vec3(v[0]->tangent) + b1 * glm::vec3(v[1]->tangent) + b2 * glm::vec3(v[2]->tangent);
            texel.tangent = orthonormalTo(texel.normal, tangent);
            const float sign = v[0]->tangent.w < 0.0f ? -1.0f : 1.0f;
            texel.bitangent = sign * glm::cross(texel.normal, texel.tangent);
            texel.footprintM = footprint;
            texel.part = part;
            texel.covered = true;
        }
    }
}

}  // namespace

SurfaceMap rasteriseSurface(const MeshData& mesh, const std::vector<uint8_t>& trianglePart, int width, int height) {
    SurfaceMap map;
    map.width = width;
    map.height = height;
    map.texels.resize(static_cast<size_t>(width) * static_cast<size_t>(height));
    // Bands of rows, one task each, so that no two tasks write the same texel.
    constexpr int kBandRows = 32;
    const int bands = (height + kBandRows - 1) / kBandRows;
    forEachRow(bands, [&](int band) {
        const int rowBegin = band * kBandRows;
        const int rowEnd = std::min(height, rowBegin + kBandRows);
        const float vBegin = static_cast<float>(rowBegin) / static_cast<float>(height);
        const float vEnd = static_cast<float>(rowEnd) / static_cast<float>(height);
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            const float v0 = mesh.vertices[mesh.indices[3 * t]].uv.y;
            const float v1 = mesh.vertices[mesh.indices[3 * t + 1]].uv.y;
            const float v2 = mesh.vertices[mesh.indices[3 * t + 2]].uv.y;
            const float margin = 1.0f / static_cast<float>(height);
            if (std::max(v0, std::max(v1, v2)) < vBegin - margin || std::min(v0, std::min(v1, v2)) > vEnd + margin)
                continue;
            const uint8_t part = trianglePart.empty() ? uint8_t(0) : trianglePart[t];
            rasteriseTriangle(mesh, t, part, rowBegin, rowEnd, map);
        }
    });
    return map;
}

void forEachRow(int height, const std::function<void(int row)>& body) {
    const int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 16u));
    std::vector<std::thread> workers;
    for (int worker = 0; worker < threads; ++worker) {
        workers.emplace_back([=, &body] {
            for (int row = worker; row < height; row += threads) body(row);
        });
    }
    for (std::thread& w : workers) w.join();
}

void fillGutters(Image& image, const SurfaceMap& surface, int rings, const glm::vec4& background, bool unitVectors) {
    const int w = image.width;
    const int h = image.height;
    std::vector<uint8_t> filled(image.texels.size());
    for (size_t i = 0; i < filled.size(); ++i) filled[i] = surface.texels[i].covered ? 1 : 0;

    std::vector<uint8_t> next = filled;
    for (int ring = 0; ring < rings; ++ring) {
        // A texel filled in this ring is not read in it, so rows are independent.
        forEachRow(h, [&](int y) {
            for (int x = 0; x < w; ++x) {
                const size_t i = static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x);
                if (filled[i]) continue;
                glm::vec4 sum(0.0f);
                int count = 0;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx;
                        const int ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        const size_t j = static_cast<size_t>(ny) * static_cast<size_t>(w) + static_cast<size_t>(nx);
                        if (!filled[j]) continue;
                        sum += image.texels[j];
                        ++count;
                    }
                }
                if (count == 0) continue;
                glm::vec4 mean = sum / static_cast<float>(count);
                if (unitVectors) {
                    const glm::vec3 n = glm::normalize(glm::vec3(mean) * 2.0f - 1.0f);
                    mean = glm::vec4(n * 0.5f + 0.5f, mean.w);
                }
                image.texels[i] = mean;
                next[i] = 1;
            }
        });
        filled = next;
    }
    for (size_t i = 0; i < filled.size(); ++i)
        if (!filled[i]) image.texels[i] = background;
}

}  // namespace dermis
