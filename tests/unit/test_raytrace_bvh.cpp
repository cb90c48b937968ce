// The reference's ray tracers against brute force, the in-house BVH and
// Embree's alike: the same nearest hits (and which side of the triangle they
// meet) and the same any-hit answers on random rays through random (and some
// degenerate) triangles.
#include "raytrace/Bvh.h"
#include "raytrace/EmbreeBvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dermis::raytrace;

namespace {

// Ray-triangle intersection through the triangle's plane in double precision: an
// independent formulation of what Moller-Trumbore computes.
bool bruteForceHit(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b,
                   const glm::dvec3& c, double* t) {
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double denominator = glm::dot(n, d);
    if (std::fabs(denominator) < 1e-300) return false;
    *t = glm::dot(n, a - o) / denominator;
    const glm::dvec3 p = o + *t * d;
    // Inside when p is on the inner side of all three edges.
    const double s0 = glm::dot(glm::cross(b - a, p - a), n);
    const double s1 = glm::dot(glm::cross(c - b, p - b), n);
    const double s2 = glm::dot(glm::cross(a - c, p - c), n);
    return s0 >= 0.0 && s1 >= 0.0 && s2 >= 0.0;
}

struct Scene {
    std::vector<glm::vec3> corners;
};

Scene randomTriangles(std::mt19937& rng, int count) {
    std::uniform_real_distribution<float> position(-1.0f, 1.0f);
    std::uniform_real_distribution<float> offset(-0.15f, 0.15f);
    Scene scene;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 centre(position(rng), position(rng), position(rng));
        for (int c = 0; c < 3; ++c) scene.corners.push_back(centre + glm::vec3(offset(rng), offset(rng), offset(rng)));
    }
    // Degenerate ones: a point and a line. They must never be hit (nor crash the build).
    scene.corners.insert(scene.corners.end(), 3, glm::vec3(0.1f, 0.2f, 0.3f));
    scene.corners.insert(scene.corners.end(), {glm::vec3(0.0f), glm::vec3(0.5f), glm::vec3(1.0f)});
    return scene;
}

template <class Tracer>
class ReferenceBvh : public ::testing::Test {};
using Tracers = ::testing::Types<Bvh, EmbreeBvh>;
TYPED_TEST_SUITE(ReferenceBvh, Tracers);

}  // namespace

TYPED_TEST(ReferenceBvh, ClosestAndAnyHitsMatchBruteForce) {
    std::mt19937 rng(12345);
    const Scene scene = randomTriangles(rng, 2000);
    const TypeParam bvh = TypeParam::build(scene.corners);
    ASSERT_EQ(bvh.triangleCount(), scene.corners.size() / 3);
    for (uint32_t t = 0; t < bvh.triangleCount(); t += 97) {
        for (int k = 0; k < 3; ++k) ASSERT_EQ(bvh.corner(t, k), scene.corners[3 * t + size_t(k)]) << "triangle " << t;
    }
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int hits = 0, backFaces = 0;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 origin(1.5f * unit(rng), 1.5f * unit(rng), 1.5f * unit(rng));
        glm::vec3 direction(unit(rng), unit(rng), unit(rng));
        if (i % 10 == 0) direction = glm::vec3(0.0f, 0.0f, unit(rng) < 0.0f ? -1.0f : 1.0f);  // axis-aligned rays
        if (glm::length(direction) < 1e-3f) continue;
        const float tMax = i % 3 == 0 ? 0.7f : 1e30f;

        double nearest = INFINITY;
        int nearestTriangle = -1;
        for (size_t t = 0; t < scene.corners.size() / 3; ++t) {
            double tHit;
            if (bruteForceHit(origin, direction, scene.corners[3 * t], scene.corners[3 * t + 1], scene.corners[3 * t + 2],
                              &tHit) &&
                tHit > 1e-6 && tHit < tMax && tHit < nearest) {
                nearest = tHit;
                nearestTriangle = int(t);
            }
        }
        BvhHit hit;
        const bool found = bvh.closestHit(Ray{origin, direction}, 1e-6f, tMax, &hit);
        ASSERT_EQ(found, nearestTriangle >= 0) << "ray " << i;
        ASSERT_EQ(bvh.anyHit(Ray{origin, direction}, 1e-6f, tMax), found) << "ray " << i;
        if (!found) continue;
        ++hits;
        EXPECT_NEAR(hit.t, nearest, 1e-4 * std::max(1.0, nearest)) << "ray " << i;
        // Different triangles only where two surfaces meet the ray at the same distance.
        if (int(hit.triangle) != nearestTriangle) {
            EXPECT_NEAR(hit.t, nearest, 1e-6) << "ray " << i;
        }
        const glm::vec3 a = scene.corners[3 * hit.triangle], b = scene.corners[3 * hit.triangle + 1],
                        c = scene.corners[3 * hit.triangle + 2];
        const glm::vec3 p = a + hit.u * (b - a) + hit.v * (c - a);
        EXPECT_LT(glm::length(p - (origin + hit.t * direction)), 1e-4f) << "ray " << i;
        const bool backFace = glm::dot(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a)), glm::dvec3(direction)) > 0.0;
        EXPECT_EQ(hit.backFace, backFace) << "ray " << i;
        backFaces += backFace ? 1 : 0;
    }
    EXPECT_GT(backFaces, 100);  // both sides are met
    EXPECT_LT(backFaces, hits - 100);
    EXPECT_GT(hits, 300);  // the test means something
}

TYPED_TEST(ReferenceBvh, EmptyAndSingleTriangle) {
    const TypeParam empty = TypeParam::build({});
    BvhHit hit;
    EXPECT_FALSE(empty.closestHit(Ray{glm::vec3(0.0f), glm::vec3(0, 0, -1)}, 0.0f, 1e30f, &hit));
    EXPECT_FALSE(empty.anyHit(Ray{glm::vec3(0.0f), glm::vec3(0, 0, -1)}, 0.0f, 1e30f));

    const TypeParam one = TypeParam::build({glm::vec3(-1, -1, -2), glm::vec3(1, -1, -2), glm::vec3(0, 1, -2)});
    ASSERT_TRUE(one.closestHit(Ray{glm::vec3(0.0f), glm::vec3(0, 0, -1)}, 0.0f, 1e30f, &hit));
    EXPECT_FLOAT_EQ(hit.t, 2.0f);
    EXPECT_FALSE(one.anyHit(Ray{glm::vec3(0.0f), glm::vec3(0, 0, -1)}, 0.0f, 1.5f));  // beyond tMax
    EXPECT_FALSE(one.anyHit(Ray{glm::vec3(0.0f), glm::vec3(0, 0, 1)}, 0.0f, 1e30f));  // behind the origin
}
