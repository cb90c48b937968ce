// Levels of detail (mesh/MeshLod.h) and their choice per frame
// (plan/LevelOfDetail.h), against closed forms: a sphere's true surface for
// the levels' error, and the rule's thresholds for the choice.
#include "mesh/MeshLod.h"
#include "mesh/MeshLodCache.h"
#include "plan/LevelOfDetail.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dermis {
namespace {

// A latitude-longitude unit sphere, made here (not by the engine), in two
// draw ranges: the northern and the southern hemisphere with materials 0 and 1.
Model unitSphere(int segments, int rings) {
    Model model;
    for (int r = 0; r <= rings; ++r) {
        const float theta = glm::pi<float>() * float(r) / float(rings);
        for (int s = 0; s <= segments; ++s) {
            const float phi = glm::two_pi<float>() * float(s) / float(segments);
            Vertex v;
            v.position = glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            v.normal = v.position;
            v.uv = glm::vec2(float(s) / float(segments), float(r) / float(rings));
            model.mesh.vertices.push_back(v);
        }
    }
    const auto at = [segments](int r, int s) { return uint32_t(r * (segments + 1) + s); };
    for (int half = 0; half < 2; ++half) {
        Submesh range;
        range.firstIndex = uint32_t(model.mesh.indices.size());
        range.material = half;
        for (int r = half * rings / 2; r < (half + 1) * rings / 2; ++r) {
            for (int s = 0; s < segments; ++s) {
                for (uint32_t i : {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s), at(r + 1, s + 1), at(r, s + 1)}) {
                    model.mesh.indices.push_back(i);
                }
            }
        }
        range.indexCount = uint32_t(model.mesh.indices.size()) - range.firstIndex;
        model.submeshes.push_back(range);
    }
    return model;
}

// The largest distance from the unit sphere of the triangles' points (a
// barycentric grid on each), over the triangles indices[first, first + count).
double sphereDeviation(const MeshData& mesh, const std::vector<uint32_t>& indices) {
    double worst = 0.0;
    constexpr int kSteps = 6;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a(mesh.vertices[indices[t]].position), b(mesh.vertices[indices[t + 1]].position),
            c(mesh.vertices[indices[t + 2]].position);
        for (int i = 0; i <= kSteps; ++i) {
            for (int j = 0; i + j <= kSteps; ++j) {
                const double u = double(i) / kSteps, v = double(j) / kSteps;
                worst = std::max(worst, std::abs(1.0 - glm::length(a + u * (b - a) + v * (c - a))));
            }
        }
    }
    return worst;
}

TEST(LevelOfDetail, EachLevelHasAboutAQuarterOfTheTrianglesAndKeepsTheRanges) {
    const Model sphere = unitSphere(128, 64);
    const std::vector<LodLevel> levels = makeLodLevels(sphere.mesh, sphere.drawRanges());
    ASSERT_GE(levels.size(), 2u);
    size_t previous = sphere.mesh.triangleCount();
    for (const LodLevel& level : levels) {
        // The simplifier aims at kLodTriangleRatio of the full mesh's count per level; the
        // locked borders of the two halves keep a few more.
        EXPECT_LE(double(level.triangleCount()), 0.3 * double(previous)) << level.triangleCount();
        EXPECT_GE(double(level.triangleCount()), 0.2 * double(previous)) << level.triangleCount();
        previous = level.triangleCount();
        ASSERT_EQ(level.ranges.size(), 2u);
        EXPECT_EQ(level.ranges[0].material, 0);
        EXPECT_EQ(level.ranges[1].material, 1);
        EXPECT_EQ(level.ranges[0].firstIndex, 0u);
        EXPECT_EQ(level.ranges[1].firstIndex, level.ranges[0].indexCount);
        EXPECT_EQ(level.ranges[0].indexCount + level.ranges[1].indexCount, level.indices.size());
        for (uint32_t index : level.indices) ASSERT_LT(index, sphere.mesh.vertices.size());
    }
}

// The reported error bounds how far each level's surface lies from the true
// sphere, plus the full mesh's own deviation, measured on a finer barycentric
// grid of every triangle (6 steps per edge, against the engine's 3), and is
// not far above it: at most 1.5x the deviation, since the full mesh lies within
// its own small deviation of the sphere. With the simplifier's own estimate
// (meshopt_simplify's result error times the mesh's scale, as before the
// error was measured) it fails: the deviation, less the full mesh's, reached
// 1.81x that estimate here.
TEST(LevelOfDetail, TheReportedErrorBoundsTheDeviationFromTheSphere) {
    const Model sphere = unitSphere(128, 64);
    const double fullDeviation = sphereDeviation(sphere.mesh, sphere.mesh.indices);
    const std::vector<LodLevel> levels = makeLodLevels(sphere.mesh, sphere.drawRanges());
    ASSERT_FALSE(levels.empty());
    float previousError = 0.0f;
    for (size_t l = 0; l < levels.size(); ++l) {
        const double deviation = sphereDeviation(sphere.mesh, levels[l].indices);
        std::printf("[ measured ] level %zu: %zu triangles, reported error %.5f, deviation %.5f (full mesh %.5f)\n",
                    l + 1, levels[l].triangleCount(), levels[l].errorObject, deviation, fullDeviation);
        EXPECT_LE(deviation, double(levels[l].errorObject) + fullDeviation) << "level " << l + 1;
        EXPECT_LE(double(levels[l].errorObject), 1.5 * deviation) << "level " << l + 1;
        EXPECT_GT(deviation, fullDeviation) << "level " << l + 1 << " is no coarser than the full mesh";
        EXPECT_GE(levels[l].errorObject, previousError) << "a coarser level reports less error";
        EXPECT_LE(levels[l].errorObject, kMaxLodRelativeError * 2.0f) << "kept past the relative error limit";
        previousError = levels[l].errorObject;
    }
}

bool sameLevels(const std::vector<LodLevel>& a, const std::vector<LodLevel>& b) {
    if (a.size() != b.size()) return false;
    for (size_t l = 0; l < a.size(); ++l) {
        if (a[l].indices != b[l].indices || a[l].errorObject != b[l].errorObject || a[l].ranges.size() != b[l].ranges.size())
            return false;
        for (size_t r = 0; r < a[l].ranges.size(); ++r) {
            const Submesh &x = a[l].ranges[r], &y = b[l].ranges[r];
            if (x.firstIndex != y.firstIndex || x.indexCount != y.indexCount || x.material != y.material) return false;
        }
    }
    return true;
}

// The disk cache (mesh/MeshLodCache.h) gives back the levels made in this
// process, bit for bit, and a file that holds other content is refused.
TEST(LevelOfDetail, CachedLevelsAreTheMadeOnes) {
    const test::TempDir dir;
    const test::ScopedEnvironmentVariable cache("DERMIS_CACHE_DIR", dir.path().c_str());
    const Model sphere = unitSphere(128, 64);
    const std::vector<LodLevel> made = makeLodLevels(sphere.mesh, sphere.drawRanges());
    bool fromCache = true;
    const std::vector<LodLevel> first = loadOrMakeLodLevels(sphere.mesh, sphere.drawRanges(), &fromCache);
    EXPECT_FALSE(fromCache) << "an empty cache directory";
    const std::vector<LodLevel> second = loadOrMakeLodLevels(sphere.mesh, sphere.drawRanges(), &fromCache);
    EXPECT_TRUE(fromCache);
    ASSERT_FALSE(made.empty());
    EXPECT_TRUE(sameLevels(made, first));
    EXPECT_TRUE(sameLevels(made, second));

    // The payload's checks: an index past the mesh's vertices, a cut payload, trailing bytes.
    std::vector<uint8_t> bytes = encodeLodLevels(made);
    std::vector<LodLevel> decoded;
    EXPECT_TRUE(decodeLodLevels(bytes, sphere.mesh.vertices.size(), decoded));
    EXPECT_TRUE(sameLevels(made, decoded));
    EXPECT_FALSE(decodeLodLevels(bytes, 10, decoded)) << "indices past 10 vertices";
    std::vector<uint8_t> cut(bytes.begin(), bytes.end() - 4);
    EXPECT_FALSE(decodeLodLevels(cut, sphere.mesh.vertices.size(), decoded));
    bytes.push_back(0);
    EXPECT_FALSE(decodeLodLevels(bytes, sphere.mesh.vertices.size(), decoded));
}

TEST(LevelOfDetail, SmallMeshesGetNoLevels) {
    const Model sphere = unitSphere(16, 8);  // 256 triangles
    EXPECT_TRUE(makeLodLevels(sphere.mesh, sphere.drawRanges()).empty());
}

// Errors 0.1, 0.4 and 1.6 object units: at p pixels per unit, level k fits
// when its error x p <= the limit.
const std::vector<float> kErrors = {0.1f, 0.4f, 1.6f};

TEST(LevelOfDetail, TheChoiceIsTheCoarsestLevelWithinTheLimit) {
    EXPECT_EQ(chooseLodLevel(kErrors, 1.0f, 1.0f, -1), 2);   // 0.4 <= 1 < 1.6
    EXPECT_EQ(chooseLodLevel(kErrors, 0.5f, 1.0f, -1), 3);   // 0.8 <= 1
    EXPECT_EQ(chooseLodLevel(kErrors, 5.0f, 1.0f, -1), 1);   // 0.5 <= 1 < 2
    EXPECT_EQ(chooseLodLevel(kErrors, 20.0f, 1.0f, -1), 0);  // 2 > 1
    EXPECT_EQ(chooseLodLevel(kErrors, 10.0f, 1.0f, -1), 1);  // exactly at the limit: fits
    EXPECT_EQ(chooseLodLevel(kErrors, 1.0f, 0.0f, -1), 0);   // off
    EXPECT_EQ(chooseLodLevel(kErrors, std::nanf(""), 1.0f, -1), 0);
    EXPECT_EQ(chooseLodLevel({}, 1.0f, 1.0f, -1), 0);
}

TEST(LevelOfDetail, HysteresisCoarsensOnlyWellWithinTheLimitAndRefinesAtOnce) {
    // From level 1, level 2 (0.4 p px) is taken only once 0.4 p <= 0.75.
    EXPECT_EQ(chooseLodLevel(kErrors, 2.25f, 1.0f, 1), 1);   // 0.9 px: fits, but not within 0.75
    EXPECT_EQ(chooseLodLevel(kErrors, 1.8f, 1.0f, 1), 2);    // 0.72 px
    // From level 2, back to level 1 as soon as 0.4 p > 1.
    EXPECT_EQ(chooseLodLevel(kErrors, 2.4f, 1.0f, 2), 2);    // 0.96 px: level 2 still fits, stays
    EXPECT_EQ(chooseLodLevel(kErrors, 2.6f, 1.0f, 2), 1);    // 1.04 px
    // A previous level past the last is clamped.
    EXPECT_EQ(chooseLodLevel(kErrors, 0.5f, 1.0f, 7), 3);
}

// A character wobbling around a switching distance does not flicker: with the
// scale jittering by 10% around level 2's limit, the level changes once.
TEST(LevelOfDetail, AJitteringScaleDoesNotFlicker) {
    int level = -1;
    int changes = 0;
    for (int frame = 0; frame < 200; ++frame) {
        const float pixelsPerUnit = 2.5f * (1.0f + 0.1f * std::sin(0.7f * float(frame)));  // 0.4 p in 0.9 .. 1.1 px
        const int next = chooseLodLevel(kErrors, pixelsPerUnit, 1.0f, level);
        if (level >= 0 && next != level) ++changes;
        level = next;
    }
    EXPECT_LE(changes, 1);
}

}  // namespace
}  // namespace dermis
