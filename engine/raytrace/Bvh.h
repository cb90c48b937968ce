#pragma once
// A bounding-volume hierarchy over world-space triangles for the CPU
// reference: closest hits for primary rays, any hits for shadow rays. Binned
// surface-area-heuristic build (Wald 2007, "On fast construction of SAH-based
// bounding volume hierarchies"), Moller-Trumbore triangle tests (1997).

#include "raytrace/TriangleScene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis::raytrace {

class Bvh final : public TriangleScene {
public:
    // Three corners per triangle, in order. Degenerate triangles are kept but never hit.
    static Bvh build(const std::vector<glm::vec3>& cornersM);

    // The nearest hit with tMin < t < tMax, if any.
    bool closestHit(const Ray& ray, float tMin, float tMax, BvhHit* hit) const override;
    // Whether anything lies along the ray with tMin < t < tMax.
    bool anyHit(const Ray& ray, float tMin, float tMax) const override;

    size_t triangleCount() const override { return mTriangleIds.size(); }
    size_t nodeCount() const { return mNodes.size(); }

private:
    struct Node {
        glm::vec3 boundsMin{0.0f};
        uint32_t firstOrChild = 0;  // leaf: first triangle slot; inner: index of the left child (right = left + 1)
        glm::vec3 boundsMax{0.0f};
        uint32_t count = 0;  // triangles in a leaf; 0 for an inner node
    };
    struct Triangle {
        glm::vec3 v0;
        glm::vec3 edge1;
        glm::vec3 edge2;
    };

    template <bool kAnyHit>
    bool traverse(const Ray& ray, float tMin, float tMax, BvhHit* hit) const;

    std::vector<Node> mNodes;
    std::vector<Triangle> mTriangles;     // in leaf order
    std::vector<uint32_t> mTriangleIds;  // leaf slot -> original index
};

}  // namespace dermis::raytrace
