// Distances to triangles (mesh/SurfaceDistance.h), against closed forms: a
// point's distance to a triangle's plane, edge and corner, and to a sphere
// made of triangles.
#include "mesh/SurfaceDistance.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace dermis {
namespace {

TEST(SurfaceDistance, ClosestPointsOnATriangleMatchTheClosedForms) {
    const glm::vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    // Above the inside: straight down.
    EXPECT_NEAR(glm::length(closestPointOnTriangle({0.5f, 0.5f, 3.0f}, a, b, c) - glm::vec3(0.5f, 0.5f, 0.0f)), 0.0f, 1e-6f);
    // Beyond the corner a: a.
    EXPECT_NEAR(glm::length(closestPointOnTriangle({-1.0f, -2.0f, 1.0f}, a, b, c) - a), 0.0f, 1e-6f);
    // Beyond the hypotenuse bc: its foot (1.5, 1.5) - (0.5, 0.5) projected onto bc.
    EXPECT_NEAR(glm::length(closestPointOnTriangle({2.0f, 2.0f, 0.0f}, a, b, c) - glm::vec3(1.0f, 1.0f, 0.0f)), 0.0f, 1e-6f);
    // Beside the edge ab: its foot.
    EXPECT_NEAR(glm::length(closestPointOnTriangle({1.2f, -0.7f, 0.4f}, a, b, c) - glm::vec3(1.2f, 0.0f, 0.0f)), 0.0f, 1e-6f);
}

// A latitude-longitude unit sphere: points at radius r lie 1 - r (inside)
// or r - 1 (outside) from it, less the facets' sag, which is at most
// 1 - cos(pi / rings) ~ 1.2e-3 here. The limit caps the answer.
TEST(SurfaceDistance, PointsNearAndFarFromASphereOfTriangles) {
    MeshData sphere;
    constexpr int kSegments = 128, kRings = 64;
    for (int r = 0; r <= kRings; ++r) {
        const float theta = glm::pi<float>() * float(r) / kRings;
        for (int s = 0; s <= kSegments; ++s) {
            const float phi = glm::two_pi<float>() * float(s) / kSegments;
            Vertex v;
            v.position = glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            sphere.vertices.push_back(v);
        }
    }
    const auto at = [](int r, int s) { return uint32_t(r * (kSegments + 1) + s); };
    for (int r = 0; r < kRings; ++r)
        for (int s = 0; s < kSegments; ++s)
            for (uint32_t i : {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1)})
                sphere.indices.push_back(i);
    const TriangleDistance distance(sphere, sphere.indices);
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    const float sag = 1.0f - std::cos(glm::pi<float>() / kRings);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 direction = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)));
        const float radius = 1.0f + 0.3f * unit(random);
        const float d = distance.distance(radius * direction, 10.0f);
        EXPECT_NEAR(d, std::abs(radius - 1.0f), sag) << "radius " << radius;
    }
    EXPECT_FLOAT_EQ(distance.distance({0.0f, 0.0f, 0.0f}, 0.25f), 0.25f) << "the limit caps a far point";
    const std::vector<uint32_t> none;
    EXPECT_EQ(TriangleDistance(sphere, none).distance({0, 0, 0}, 5.0f), 5.0f);
}

}  // namespace
}  // namespace dermis
