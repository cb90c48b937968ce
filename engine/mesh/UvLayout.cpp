#include "mesh/UvLayout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <queue>
#include <unordered_map>
#include <utility>

namespace dermis {
namespace {

// UV positions are compared on a 2^-20 grid: vertices of one chart that share
// a UV are the same surface point (a normal or tangent split), and an edge
// whose UV endpoints occur in one triangle only lies on a chart border.
constexpr float kUvGrid = 1048576.0f;
// A triangle whose spatial area is below this fraction of its squared edge
// lengths is degenerate in space.
constexpr float kDegenerateArea = 1e-9f;
constexpr float kDegenerateUvArea = 1e-14f;
// The chart beyond a seam must reach this share of the seam probe from it.
constexpr float kSeamProbeReach = 0.5f;

uint64_t uvKey(const glm::vec2& uv) {
    const auto quantise = [](float x) {
        return static_cast<uint32_t>(static_cast<int32_t>(std::lround(double(x) * kUvGrid)));
    };
    return (uint64_t(quantise(uv.x)) << 32) | uint64_t(quantise(uv.y));
}

struct PairHash {
    size_t operator()(const std::pair<uint32_t, uint32_t>& p) const {
        return std::hash<uint64_t>()((uint64_t(p.first) << 32) | p.second);
    }
};

float percentile(std::vector<float> values, float fraction) {
    if (values.empty()) return 0.0f;
    const auto k = static_cast<size_t>(fraction * float(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

void accumulateDerivatives(const MeshData& mesh, UvLayout& out) {
    const size_t n = mesh.vertices.size();
    std::vector<float> weights(n, 0.0f);
    double surfaceArea = 0.0, uvlessArea = 0.0;
    out.dPdu.assign(n, glm::vec3(0.0f));
    out.dPdv.assign(n, glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        if (i[0] >= n || i[1] >= n || i[2] >= n) continue;
        const Vertex& a = mesh.vertices[i[0]];
        const glm::vec3 e1 = mesh.vertices[i[1]].position - a.position;
        const glm::vec3 e2 = mesh.vertices[i[2]].position - a.position;
        const glm::vec2 d1 = mesh.vertices[i[1]].uv - a.uv;
        const glm::vec2 d2 = mesh.vertices[i[2]].uv - a.uv;
        const float det = d1.x * d2.y - d2.x * d1.y;
        const float spatialArea = glm::length(glm::cross(e1, e2));
        if (!(spatialArea > kDegenerateArea * (glm::dot(e1, e1) + glm::dot(e2, e2)))) continue;
        surfaceArea += spatialArea;
        if (!(std::abs(det) >= kDegenerateUvArea)) {
            uvlessArea += spatialArea;
            continue;
        }
        // P(uv) is linear over the triangle: [e1 e2] = [dP/du dP/dv] [d1 d2].
        const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        if (!std::isfinite(glm::dot(dPdu, dPdu)) || !std::isfinite(glm::dot(dPdv, dPdv))) continue;
        // Weighting by UV area keeps a UV sliver (tiny det, large dP/du) from dominating.
        const float weight = std::abs(det);
        for (uint32_t v : i) {
            out.dPdu[v] += weight * dPdu;
            out.dPdv[v] += weight * dPdv;
            weights[v] += weight;
        }
    }
    out.uvlessSurfaceFraction = surfaceArea > 0.0 ? float(uvlessArea / surfaceArea) : 1.0f;
    for (size_t v = 0; v < n; ++v) {
        if (weights[v] > 0.0f) {
            out.dPdu[v] /= weights[v];
            out.dPdv[v] /= weights[v];
        }
    }
}

// Positions are compared bit for bit: the two sides of a seam are split
// copies of one vertex.
struct PositionHash {
    size_t operator()(const glm::vec3& p) const {
        const std::hash<float> h;
        return h(p.x) ^ (h(p.y) * 0x9e3779b97f4a7c15ull) ^ (h(p.z) * 0xc2b2ae3d27d4eb4full);
    }
};

void computeBorderDistances(const MeshData& mesh, float seamProbe, UvLayout& out) {
    const size_t n = mesh.vertices.size();
    // Nodes: distinct UV positions.
    std::unordered_map<uint64_t, uint32_t> nodeOfKey;
    std::vector<uint32_t> nodeOfVertex(n);
    std::vector<uint32_t> vertexOfNode;
    for (size_t v = 0; v < n; ++v) {
        const auto inserted = nodeOfKey.emplace(uvKey(mesh.vertices[v].uv), static_cast<uint32_t>(nodeOfKey.size()));
        nodeOfVertex[v] = inserted.first->second;
        if (inserted.second) vertexOfNode.push_back(static_cast<uint32_t>(v));
    }
    const size_t nodes = nodeOfKey.size();

    std::unordered_map<std::pair<uint32_t, uint32_t>, int, PairHash> edgeUses;
    std::vector<std::vector<std::pair<uint32_t, float>>> neighbours(nodes);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t va = mesh.indices[t + static_cast<size_t>(k)];
            const uint32_t vb = mesh.indices[t + static_cast<size_t>((k + 1) % 3)];
            if (va >= n || vb >= n) continue;
            uint32_t a = nodeOfVertex[va];
            uint32_t b = nodeOfVertex[vb];
            if (a == b) continue;
            if (a > b) std::swap(a, b);
            if (edgeUses[{a, b}]++ == 0) {
                const float length = glm::length(mesh.vertices[va].position - mesh.vertices[vb].position);
                neighbours[a].push_back({b, length});
                neighbours[b].push_back({a, length});
            }
        }
    }

    // Dijkstra from every node on an edge that only one triangle uses,
    // remembering which border node each node is nearest to.
    constexpr uint32_t kNone = ~0u;
    std::vector<float> distance(nodes, kFarFromBorder);
    std::vector<uint32_t> nearestBorder(nodes, kNone);
    std::unordered_multimap<glm::vec3, uint32_t, PositionHash> borderNodesAt;
    using Entry = std::pair<float, uint32_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (const auto& [edge, uses] : edgeUses) {
        if (uses != 1) continue;
        for (uint32_t node : {edge.first, edge.second}) {
            if (distance[node] > 0.0f) {
                distance[node] = 0.0f;
                nearestBorder[node] = node;
                borderNodesAt.emplace(mesh.vertices[vertexOfNode[node]].position, node);
                queue.push({0.0f, node});
            }
        }
    }
    while (!queue.empty()) {
        const auto [d, node] = queue.top();
        queue.pop();
        if (d > distance[node]) continue;
        for (const auto& [next, length] : neighbours[node]) {
            const float candidate = d + length;
            if (candidate < distance[next]) {
                distance[next] = candidate;
                nearestBorder[next] = nearestBorder[node];
                queue.push({candidate, next});
            }
        }
    }
    // Each border node's strip: the nodes it is the nearest border node of.
    std::vector<std::vector<uint32_t>> strip(nodes);
    for (uint32_t node = 0; node < nodes; ++node) {
        if (nearestBorder[node] != kNone) strip[nearestBorder[node]].push_back(node);
    }
    // The strip's node nearest to seamProbe from the border (its farthest,
    // where the strip is shorter).
    const auto probeNode = [&](uint32_t border) {
        uint32_t best = border;
        for (uint32_t node : strip[border]) {
            if (std::abs(distance[node] - seamProbe) < std::abs(distance[best] - seamProbe)) best = node;
        }
        return best;
    };
    const auto normalAt = [&](uint32_t node) { return glm::normalize(mesh.vertices[vertexOfNode[node]].normal); };
    // Per border node: (partner UV, 1, turn), worked out once.
    std::unordered_map<uint32_t, glm::vec4> continuationOf;
    const auto continuation = [&](uint32_t border) {
        const auto known = continuationOf.find(border);
        if (known != continuationOf.end()) return known->second;
        glm::vec4 result(0.0f, 0.0f, 0.0f, -1.0f);
        // The other border node at the border vertex's position: where a
        // seam's other side is (at a corner where three charts meet, either).
        const auto [first, last] = borderNodesAt.equal_range(mesh.vertices[vertexOfNode[border]].position);
        for (auto it = first; it != last; ++it) {
            if (it->second == border) continue;
            // A chart beyond that ends within half the probe (a strip round a
            // box's thin end) is one step of a turn that goes on past it: its
            // light is not what lies beyond the border. No continuation there.
            float reach = 0.0f;
            for (uint32_t node : strip[it->second]) reach = std::max(reach, distance[node]);
            if (reach < kSeamProbeReach * seamProbe) break;
            const float turn = -glm::dot(normalAt(probeNode(border)), normalAt(probeNode(it->second)));
            result = glm::vec4(mesh.vertices[vertexOfNode[it->second]].uv, 1.0f, std::isfinite(turn) ? turn : -1.0f);
            break;
        }
        continuationOf.emplace(border, result);
        return result;
    };
    out.borderDistance.resize(n);
    out.seamContinuation.assign(n, glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    for (size_t v = 0; v < n; ++v) {
        const uint32_t node = nodeOfVertex[v];
        out.borderDistance[v] = std::min(distance[node], kFarFromBorder);
        if (nearestBorder[node] != kNone) out.seamContinuation[v] = continuation(nearestBorder[node]);
    }
}

// Rasterises every triangle's UV footprint onto texel centres of the grid
// (half-open edge test, so a centre on an edge two triangles share counts
// once): the share of the grid's texels covered, and of those the share
// covered more than once.
void coverageAndOverlap(const MeshData& mesh, UvLayout& out) {
    constexpr int n = kUvOverlapGrid;
    std::vector<uint8_t> count(size_t(n) * n, 0);
    const size_t vertices = mesh.vertices.size();
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
        if (i[0] >= vertices || i[1] >= vertices || i[2] >= vertices) continue;
        glm::vec2 p[3];
        for (int k = 0; k < 3; ++k) p[k] = mesh.vertices[i[k]].uv * float(n);
        const float area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
        if (!(std::abs(area) > 0.0f)) continue;
        if (area < 0.0f) std::swap(p[1], p[2]);  // counter-clockwise
        const float minX = std::min({p[0].x, p[1].x, p[2].x}), maxX = std::max({p[0].x, p[1].x, p[2].x});
        const float minY = std::min({p[0].y, p[1].y, p[2].y}), maxY = std::max({p[0].y, p[1].y, p[2].y});
        const int x0 = std::max(0, int(std::ceil(minX - 0.5f))), x1 = std::min(n - 1, int(std::floor(maxX - 0.5f)));
        const int y0 = std::max(0, int(std::ceil(minY - 0.5f))), y1 = std::min(n - 1, int(std::floor(maxY - 0.5f)));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 c(float(x) + 0.5f, float(y) + 0.5f);
                bool inside = true;
                for (int k = 0; k < 3 && inside; ++k) {
                    const glm::vec2 a = p[k], b = p[(k + 1) % 3];
                    const float side = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
                    // Half-open: on an edge, inside only for edges pointing
                    // up, or left along a horizontal (a top-left rule).
                    inside = side > 0.0f || (side == 0.0f && (b.y > a.y || (b.y == a.y && b.x < a.x)));
                }
                uint8_t& texel = count[size_t(y) * n + size_t(x)];
                if (inside && texel < 2) ++texel;
            }
        }
    }
    size_t covered = 0, overlapped = 0;
    for (uint8_t c : count) {
        covered += c > 0;
        overlapped += c > 1;
    }
    out.uvCoverageFraction = float(double(covered) / double(count.size()));
    out.uvOverlapFraction = covered > 0 ? float(double(overlapped) / double(covered)) : 0.0f;
}

}  // namespace

UvLayout analyseUvDerivatives(const MeshData& mesh) {
    UvLayout out;
    accumulateDerivatives(mesh, out);
    return out;
}

UvLayout analyseUvLayout(const MeshData& mesh, float metresPerUnit) {
    UvLayout out;
    coverageAndOverlap(mesh, out);
    accumulateDerivatives(mesh, out);
    computeBorderDistances(mesh, kSeamProbeM / std::max(metresPerUnit, 1e-12f), out);
    std::vector<float> typical;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const float u = glm::length(out.dPdu[v]);
        const float w = glm::length(out.dPdv[v]);
        if (u > 0.0f && w > 0.0f) typical.push_back(std::sqrt(u * w));
    }
    out.medianStretch = percentile(typical, 0.5f);
    out.denseStretch = percentile(std::move(typical), 0.1f);
    return out;
}

}  // namespace dermis
