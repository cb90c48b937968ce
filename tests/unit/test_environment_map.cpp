// Environment maps (env/EnvironmentMap.h): what is refused, and the built-in sky.
#include "env/EnvironmentMap.h"
#include "env/SphericalHarmonics.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;

namespace {

TEST(EnvironmentMap, BadMapsAreRefusedNamingTheProblem) {
    auto expectError = [](const Image& map, const std::string& fragment) {
        const Status status = checkEnvironmentMap(map, "sky.exr");
        ASSERT_FALSE(status.ok()) << fragment;
        EXPECT_NE(status.error().message().find("sky.exr"), std::string::npos);
        EXPECT_NE(status.error().message().find(fragment), std::string::npos) << status.error().message();
    };
    expectError(test::solidImage(64, 64, 1.0f), "64x64 is not a latitude-longitude map: its width must be twice its height");
    expectError(test::solidImage(4, 2, 1.0f), "at least 8x4 is needed");
    Image nan = test::solidImage(16, 8, 1.0f);
    nan.at(3, 5).g = NAN;
    nan.at(7, 6).r = -1.0f;
    expectError(nan, "2 texels are not finite non-negative radiance (the first at x 3, y 5)");
    EXPECT_TRUE(checkEnvironmentMap(test::solidImage(16, 8, 1.0f), "sky.exr").ok());
}

TEST(EnvironmentMap, FilesAreReadAndUnreadableOnesRefused) {
    test::TempDir dir;
    ASSERT_TRUE(saveImage(dir.file("sky.exr"), test::solidImage(32, 16, 2.5f)).ok());
    auto map = loadEnvironmentMap(dir.file("sky.exr"));
    ASSERT_TRUE(map.ok()) << map.error().message();
    EXPECT_FLOAT_EQ(map->at(5, 5).g, 2.5f);
    auto missing = loadEnvironmentMap(dir.file("none.hdr"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message().find("none.hdr"), std::string::npos);
    ASSERT_TRUE(saveImage(dir.file("square.exr"), test::solidImage(16, 16, 1.0f)).ok());
    auto square = loadEnvironmentMap(dir.file("square.exr"));
    ASSERT_FALSE(square.ok());
    EXPECT_NE(square.error().message().find("width must be twice its height"), std::string::npos);
}

// The sun's texels carry its disc's power whatever the map's size (a disc
// smaller than a texel included), and the sky lights what faces up more
// than what faces down.
TEST(EnvironmentMap, ProceduralSunKeepsItsPowerAtEverySize) {
    ProceduralSky sky;
    sky.zenith = sky.horizon = sky.ground = glm::vec3(0.0f);
    const double disc = 2.0 * M_PI * (1.0 - std::cos(glm::radians(double(sky.sunRadiusDeg))));
    for (int height : {16, 64, 512, 2048}) {
        const Image map = makeProceduralSky(sky, height);
        double power = 0.0;
        for (int v = 0; v < map.height; ++v)
            for (int u = 0; u < map.width; ++u) power += map.at(u, v).r * latLongTexelSolidAngle(v, map.width, map.height);
        EXPECT_NEAR(power / (disc * sky.sunRadiance.r), 1.0, 1e-4) << "height " << height;
    }
    const Sh9 sh = projectLatLong(makeProceduralSky(ProceduralSky{}, 64));
    EXPECT_GT(shIrradiance(sh, glm::vec3(0, 1, 0)).b, 2.0f * shIrradiance(sh, glm::vec3(0, -1, 0)).b);
}

}  // namespace
