// The normal maps of levels of detail (mesh/LodNormalMaps.h), against a closed
// form: a quarter cylinder (radius 1) as a fine 16 x 16 grid and as a level
// of two triangles over its corners, with a normal map that tilts every
// normal the same way. The baked map must give, in the level's frame, the
// full mesh's shading normal: the cylinder's frame at the texel times the
// tilt (the fine grid's interpolated normals are the cylinder's to 1e-4).
#include "mesh/LodNormalMaps.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dermis {
namespace {

constexpr int kGrid = 16;
constexpr int kMapSize = 64;
const glm::vec3 kTilt = glm::normalize(glm::vec3(0.4f, 0.2f, 1.0f));

// u runs along the arc (theta = u pi / 2), v up the axis; the tangent follows u.
Vertex cylinderVertex(float u, float v) {
    const float theta = u * glm::half_pi<float>();
    Vertex vertex;
    vertex.position = glm::vec3(std::sin(theta), v, std::cos(theta));
    vertex.normal = glm::vec3(std::sin(theta), 0.0f, std::cos(theta));
    vertex.tangent = glm::vec4(std::cos(theta), 0.0f, -std::sin(theta), 1.0f);
    vertex.uv = glm::vec2(u, v);
    return vertex;
}

struct Cylinder {
    Model model;
    LodLevel level;
};

Cylinder quarterCylinder() {
    Cylinder c;
    MeshData& mesh = c.model.mesh;
    for (int j = 0; j <= kGrid; ++j)
        for (int i = 0; i <= kGrid; ++i) mesh.vertices.push_back(cylinderVertex(float(i) / kGrid, float(j) / kGrid));
    const auto at = [](int i, int j) { return uint32_t(j * (kGrid + 1) + i); };
    for (int j = 0; j < kGrid; ++j)
        for (int i = 0; i < kGrid; ++i)
            for (uint32_t k : {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
                mesh.indices.push_back(k);
    c.level.indices = {at(0, 0), at(kGrid, 0), at(kGrid, kGrid), at(0, 0), at(kGrid, kGrid), at(0, kGrid)};
    c.level.ranges = {{0, 6, 0}};
    Image& map = c.model.materials[0].normalMap;
    map.width = map.height = kMapSize;
    map.texels.assign(size_t(kMapSize) * kMapSize, glm::vec4(kTilt * 0.5f + 0.5f, 1.0f));
    return c;
}

// The frame (T, B, N) of unit normal n and tangent direction t, as gbuffer.frag builds it.
glm::mat3 frameOf(const glm::vec3& n, const glm::vec3& t) {
    const glm::vec3 N = glm::normalize(n);
    const glm::vec3 T = glm::normalize(t - N * glm::dot(N, t));
    return glm::mat3(T, glm::cross(N, T), N);
}

// Largest angle (radians) between the baked map's normals and the closed
// form: the full mesh's shading normal (the cylinder's frame at u times the
// tilt) in the level's frame (its two corner frames interpolated linearly in
// u, as both triangles' corners differ only in u).
double largestAngle(const Image& baked) {
    double worst = 0.0;
    for (int y = 0; y < kMapSize; ++y) {
        for (int x = 0; x < kMapSize; ++x) {
            const float u = (float(x) + 0.5f) / kMapSize;
            const float theta = u * glm::half_pi<float>();
            const glm::mat3 full = frameOf(glm::vec3(std::sin(theta), 0, std::cos(theta)),
                                           glm::vec3(std::cos(theta), 0, -std::sin(theta)));
            const glm::vec3 shading = full * kTilt;
            const glm::mat3 level =
                frameOf(glm::mix(glm::vec3(0, 0, 1), glm::vec3(1, 0, 0), u), glm::mix(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), u));
            const glm::vec3 expected = glm::transpose(level) * shading;
            const glm::vec3 got = glm::normalize(glm::vec3(baked.at(x, y)) * 2.0f - 1.0f);
            worst = std::max(worst, double(std::acos(std::clamp(glm::dot(got, expected), -1.0f, 1.0f))));
        }
    }
    return worst;
}

// Bound 2e-3 rad: the fine grid's interpolated normal departs from the
// cylinder's by under 1e-4 rad (a chord of pi/32), and float rounding adds
// less. The material's own map read in the level's frame (no bake) is off by
// up to 0.070 rad here, and a bake that keeps the full mesh's frame but forgets
// to express it in the level's (storing the shading normal as it is) by 1.53.
TEST(LodNormalMaps, TheLevelShadesWithTheFullMeshsNormals) {
    Cylinder c = quarterCylinder();
    const Image baked = bakeLodNormalMap(c.model.mesh, c.model.drawRanges(), c.level, 0, c.model.materials[0].normalMap, false);
    ASSERT_EQ(baked.width, kMapSize);
    const double angle = largestAngle(baked);
    const double unbaked = largestAngle(c.model.materials[0].normalMap);
    std::printf("[ measured ] largest angle to the closed form: baked %.2e rad, the material's own map %.3f rad\n", angle,
                unbaked);
    EXPECT_LT(angle, 2e-3);
    EXPECT_GT(unbaked, 0.05) << "the test cannot tell a bake from none";
}

TEST(LodNormalMaps, EveryLevelAndMaterialGetsAMapAndAMaterialWithoutOneNone) {
    Cylinder c = quarterCylinder();
    c.model.lods = {c.level, c.level};
    c.model.materials.push_back({});  // no normal map, and no triangles
    bakeLodNormalMaps(c.model, false);
    for (const LodLevel& level : c.model.lods) {
        ASSERT_EQ(level.normalMaps.size(), 2u);
        EXPECT_FALSE(level.normalMaps[0].empty());
        EXPECT_TRUE(level.normalMaps[1].empty());
    }
}

}  // namespace
}  // namespace dermis
