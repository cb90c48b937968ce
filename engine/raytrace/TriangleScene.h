#pragma once
// World-space triangles that rays are traced against: the interface the CPU
// reference's lighting sees, so that the in-house Bvh and Embree's (EmbreeBvh)
// serve it alike (docs/results/reference.md, "Speed", compares them).

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace dermis::raytrace {

struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // need not be unit length; t is in its units
};

struct BvhHit {
    float t = 0.0f;
    uint32_t triangle = 0;  // index in the order the triangles were given
    float u = 0.0f;         // barycentric weight of the triangle's second vertex
    float v = 0.0f;         // and of its third
    // The ray met the triangle's clockwise side: its inside, as counter-clockwise
    // triangles face out (dot(cross(b - a, c - a), direction) > 0).
    bool backFace = false;
};

class TriangleScene {
public:
    TriangleScene() = default;
    TriangleScene(const TriangleScene&) = default;
    TriangleScene(TriangleScene&&) = default;
    TriangleScene& operator=(const TriangleScene&) = default;
    TriangleScene& operator=(TriangleScene&&) = default;
    virtual ~TriangleScene() = default;
    // The nearest hit with tMin < t < tMax, if any. Thread-safe.
    virtual bool closestHit(const Ray& ray, float tMin, float tMax, BvhHit* hit) const = 0;
    // Whether anything lies along the ray with tMin < t < tMax. Thread-safe.
    virtual bool anyHit(const Ray& ray, float tMin, float tMax) const = 0;
    virtual size_t triangleCount() const = 0;
    // Corner `which` (0 to 2) of a triangle, as the build was given it.
    glm::vec3 corner(uint32_t triangle, int which) const { return mCornersM[3 * size_t(triangle) + size_t(which)]; }

protected:
    std::vector<glm::vec3> mCornersM;  // three per triangle, in the order given
};

}  // namespace dermis::raytrace
