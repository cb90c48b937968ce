#pragma once
// Intel Embree 3 (Wald et al. 2014) behind the same interface as the in-house
// Bvh: closest hits for primary rays, any hits for shadow rays, over
// world-space triangles. docs/results/reference.md ("Speed") gives its speed
// against Bvh on the reference's rays; Bvh stays as its independent check.
// Hits follow Bvh's conventions: tMin < t < tMax (Embree's interval is closed;
// the ends differ on a set of measure zero), the triangle's index in the order
// given, (u, v) the weights of its second and third corners; both faces are hit
// and degenerate triangles never are. Queries are thread-safe.

#include "raytrace/TriangleScene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::raytrace {

class EmbreeBvh final : public TriangleScene {
public:
    // Three corners per triangle, in order.
    static EmbreeBvh build(const std::vector<glm::vec3>& cornersM);

    EmbreeBvh(EmbreeBvh&& other) noexcept;
    EmbreeBvh& operator=(EmbreeBvh&& other) noexcept;
    EmbreeBvh(const EmbreeBvh&) = delete;
    EmbreeBvh& operator=(const EmbreeBvh&) = delete;
    ~EmbreeBvh() override;

    // The nearest hit with tMin < t < tMax, if any.
    bool closestHit(const Ray& ray, float tMin, float tMax, BvhHit* hit) const override;
    // Whether anything lies along the ray with tMin < t < tMax.
    bool anyHit(const Ray& ray, float tMin, float tMax) const override;

    size_t triangleCount() const override { return mTriangleCount; }

private:
    EmbreeBvh() = default;
    void release();

    void* mDevice = nullptr;  // RTCDevice
    void* mScene = nullptr;   // RTCScene
    size_t mTriangleCount = 0;
};

}  // namespace dermis::raytrace
