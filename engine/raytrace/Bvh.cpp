#include "raytrace/Bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace dermis::raytrace {
namespace {

constexpr int kBins = 16;
constexpr uint32_t kMaxLeafTriangles = 4;
constexpr int kMaxDepth = 64;  // the traversal stack's size

struct Box {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{-std::numeric_limits<float>::max()};

    void grow(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void grow(const Box& b) {
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    bool empty() const { return min.x > max.x; }
    float halfArea() const {
        if (empty()) return 0.0f;
        const glm::vec3 d = max - min;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

struct BuildTask {
    uint32_t node;
    uint32_t begin;
    uint32_t end;
    int depth;
};

// Slab test (Kay and Kajiya 1986). The inverse direction is finite (see safeInverse), so
// no 0 x infinity NaN can arise.
inline bool hitsBox(const glm::vec3& boundsMin, const glm::vec3& boundsMax, const glm::vec3& origin,
                    const glm::vec3& inverseDirection, float tMin, float tMax, float* tEnter) {
    const glm::vec3 t0 = (boundsMin - origin) * inverseDirection;
    const glm::vec3 t1 = (boundsMax - origin) * inverseDirection;
    const glm::vec3 near = glm::min(t0, t1);
    const glm::vec3 far = glm::max(t0, t1);
    const float enter = std::max(std::max(near.x, near.y), std::max(near.z, tMin));
    const float exit = std::min(std::min(far.x, far.y), std::min(far.z, tMax));
    *tEnter = enter;
    return enter <= exit;
}

// 1 / direction with zero components replaced by a tiny number of the same sign.
glm::vec3 safeInverse(const glm::vec3& direction) {
    glm::vec3 inverse;
    for (int axis = 0; axis < 3; ++axis) {
        const float d = direction[axis];
        inverse[axis] = 1.0f / (std::fabs(d) > 1e-30f ? d : std::copysign(1e-30f, d));
    }
    return inverse;
}

}  // namespace

Bvh Bvh::build(const std::vector<glm::vec3>& cornersM) {
    Bvh bvh;
    const auto count = static_cast<uint32_t>(cornersM.size() / 3);
    std::vector<Box> boxes(count);
    std::vector<glm::vec3> centroids(count);
    std::vector<uint32_t> order(count);
    for (uint32_t i = 0; i < count; ++i) {
        for (int c = 0; c < 3; ++c) boxes[i].grow(cornersM[3 * size_t(i) + size_t(c)]);
        centroids[i] = 0.5f * (boxes[i].min + boxes[i].max);
        order[i] = i;
    }
    if (count == 0) return bvh;

    bvh.mNodes.reserve(2 * size_t(count) / kMaxLeafTriangles + 1);
    bvh.mNodes.push_back(Node{});
    std::vector<BuildTask> tasks{{0, 0, count, 0}};
    while (!tasks.empty()) {
        const BuildTask task = tasks.back();
        tasks.pop_back();
        Box bounds, centroidBounds;
        for (uint32_t i = task.begin; i < task.end; ++i) {
            bounds.grow(boxes[order[i]]);
            centroidBounds.grow(centroids[order[i]]);
        }
        Node& node = bvh.mNodes[task.node];
        node.boundsMin = bounds.min;
        node.boundsMax = bounds.max;
        const uint32_t n = task.end - task.begin;
        const glm::vec3 extent = centroidBounds.max - centroidBounds.min;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);

        uint32_t split = task.begin;
        if (n > kMaxLeafTriangles && task.depth < kMaxDepth - 2 && extent[axis] > 0.0f) {
            std::array<Box, kBins> binBoxes;
            std::array<uint32_t, kBins> binCounts{};
            const float scale = float(kBins) / extent[axis];
            auto binOf = [&](uint32_t triangle) {
                const int b = static_cast<int>((centroids[triangle][axis] - centroidBounds.min[axis]) * scale);
                return std::clamp(b, 0, kBins - 1);
            };
            for (uint32_t i = task.begin; i < task.end; ++i) {
                const int b = binOf(order[i]);
                binBoxes[size_t(b)].grow(boxes[order[i]]);
                ++binCounts[size_t(b)];
            }
            // SAH cost of splitting after bin b: area(left) * count(left) + area(right) * count(right).
            std::array<float, kBins - 1> leftCost{};
            Box accumulated;
            uint32_t accumulatedCount = 0;
            for (int b = 0; b < kBins - 1; ++b) {
                accumulated.grow(binBoxes[size_t(b)]);
                accumulatedCount += binCounts[size_t(b)];
                leftCost[size_t(b)] = accumulated.halfArea() * float(accumulatedCount);
            }
            accumulated = Box{};
            accumulatedCount = 0;
            float bestCost = std::numeric_limits<float>::max();
            int bestBin = -1;
            for (int b = kBins - 1; b > 0; --b) {
                accumulated.grow(binBoxes[size_t(b)]);
                accumulatedCount += binCounts[size_t(b)];
                const float cost = leftCost[size_t(b - 1)] + accumulated.halfArea() * float(accumulatedCount);
                if (accumulatedCount > 0 && accumulatedCount < n && cost < bestCost) {
                    bestCost = cost;
                    bestBin = b - 1;
                }
            }
            if (bestBin >= 0) {
                auto middle = std::partition(order.begin() + task.begin, order.begin() + task.end,
                                             [&](uint32_t triangle) { return binOf(triangle) <= bestBin; });
                split = static_cast<uint32_t>(middle - order.begin());
            }
        }
        if (split == task.begin || split == task.end) {
            node.firstOrChild = task.begin;
            node.count = n;
            continue;
        }
        const auto left = static_cast<uint32_t>(bvh.mNodes.size());
        node.firstOrChild = left;
        node.count = 0;
        bvh.mNodes.push_back(Node{});  // invalidates `node`
        bvh.mNodes.push_back(Node{});
        tasks.push_back({left, task.begin, split, task.depth + 1});
        tasks.push_back({left + 1, split, task.end, task.depth + 1});
    }

    bvh.mTriangleIds = order;
    bvh.mCornersM.assign(cornersM.begin(), cornersM.begin() + std::ptrdiff_t(3 * size_t(count)));
    bvh.mTriangles.resize(count);
    for (uint32_t slot = 0; slot < count; ++slot) {
        const size_t base = 3 * size_t(order[slot]);
        const glm::vec3 v0 = cornersM[base];
        bvh.mTriangles[slot] = Triangle{v0, cornersM[base + 1] - v0, cornersM[base + 2] - v0};
    }
    return bvh;
}

template <bool kAnyHit>
bool Bvh::traverse(const Ray& ray, float tMin, float tMax, BvhHit* hit) const {
    if (mNodes.empty() || !(tMin < tMax)) return false;
    const glm::vec3 inverseDirection = safeInverse(ray.direction);
    std::array<uint32_t, kMaxDepth> stack;
    int top = 0;
    stack[size_t(top++)] = 0;
    bool found = false;
    float tEnter = 0.0f;
    if (!hitsBox(mNodes[0].boundsMin, mNodes[0].boundsMax, ray.origin, inverseDirection, tMin, tMax, &tEnter)) return false;
    while (top > 0) {
        const Node& node = mNodes[stack[size_t(--top)]];
        if (node.count > 0) {
            for (uint32_t slot = node.firstOrChild; slot < node.firstOrChild + node.count; ++slot) {
                // Moller-Trumbore.
                const Triangle& tri = mTriangles[slot];
                const glm::vec3 p = glm::cross(ray.direction, tri.edge2);
                const float det = glm::dot(tri.edge1, p);
                if (!(std::fabs(det) > 0.0f)) continue;
                const float inverseDet = 1.0f / det;
                const glm::vec3 s = ray.origin - tri.v0;
                const float u = glm::dot(s, p) * inverseDet;
                if (u < 0.0f || u > 1.0f) continue;
                const glm::vec3 q = glm::cross(s, tri.edge1);
                const float v = glm::dot(ray.direction, q) * inverseDet;
                if (v < 0.0f || u + v > 1.0f) continue;
                const float t = glm::dot(tri.edge2, q) * inverseDet;
                if (!(t > tMin && t < tMax) || !std::isfinite(t)) continue;
                if constexpr (kAnyHit) return true;
                tMax = t;
                found = true;
                // det = -dot(cross(edge1, edge2), direction).
                *hit = BvhHit{t, mTriangleIds[slot], u, v, det < 0.0f};
            }
            continue;
        }
        const uint32_t left = node.firstOrChild;
        float tLeft = 0.0f, tRight = 0.0f;
        const bool hitLeft = hitsBox(mNodes[left].boundsMin, mNodes[left].boundsMax, ray.origin, inverseDirection, tMin,
                                     tMax, &tLeft);
        const bool hitRight = hitsBox(mNodes[left + 1].boundsMin, mNodes[left + 1].boundsMax, ray.origin,
                                      inverseDirection, tMin, tMax, &tRight);
        // The nearer child goes on top, so closest hits shrink tMax early.
        if (hitLeft && hitRight) {
            const bool leftFirst = tLeft <= tRight;
            stack[size_t(top++)] = leftFirst ? left + 1 : left;
            stack[size_t(top++)] = leftFirst ? left : left + 1;
        } else if (hitLeft) {
            stack[size_t(top++)] = left;
        } else if (hitRight) {
            stack[size_t(top++)] = left + 1;
        }
    }
    return found;
}

bool Bvh::closestHit(const Ray& ray, float tMin, float tMax, BvhHit* hit) const {
    return traverse<false>(ray, tMin, tMax, hit);
}

bool Bvh::anyHit(const Ray& ray, float tMin, float tMax) const {
    BvhHit unused;
    return traverse<true>(ray, tMin, tMax, &unused);
}

}  // namespace dermis::raytrace
