// The dominant light taken out of an environment map (env/DominantLight.h)
// against an independent integration of the map: the light plus what is
// left gives the map's light, wherever the region lies (the longitude seam,
// a pole), and maps without a compact bright region keep everything.
#include "env/DominantLight.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The test's own quadrature, not the engine's: a texel's direction from its
// centre angles, its solid angle by Simpson's rule over sin(theta) d theta.
glm::dvec3 texelDirection(int u, int v, int width, int height) {
    const double phi = 2.0 * kPi * (u + 0.5) / width, theta = kPi * (v + 0.5) / height;
    return {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
}

double texelSolidAngle(int v, int width, int height) {
    constexpr int kSteps = 8;
    const double t0 = kPi * v / height, step = kPi / height / kSteps;
    double sum = std::sin(t0) + std::sin(t0 + kSteps * step);
    for (int i = 1; i < kSteps; ++i) sum += (i % 2 ? 4.0 : 2.0) * std::sin(t0 + i * step);
    return 2.0 * kPi / width * sum * step / 3.0;
}

// Irradiance of the map on a plane of normal n, and (n = 0) sum L d omega.
glm::dvec3 integrate(const Image& map, const glm::dvec3& normal) {
    glm::dvec3 sum(0.0);
    for (int v = 0; v < map.height; ++v)
        for (int u = 0; u < map.width; ++u) {
            const double weight = normal == glm::dvec3(0.0) ? 1.0 : std::max(glm::dot(normal, texelDirection(u, v, map.width, map.height)), 0.0);
            sum += glm::dvec3(glm::vec3(map.at(u, v))) * weight * texelSolidAngle(v, map.width, map.height);
        }
    return sum;
}

glm::vec3 towards(double azimuthDeg, double elevationDeg) {
    const double a = azimuthDeg * kPi / 180.0, e = elevationDeg * kPi / 180.0;
    return glm::vec3(float(std::cos(e) * std::sin(a)), float(std::sin(e)), float(std::cos(e) * std::cos(a)));
}

// A blue sky over a brown ground, and a disc of `sunRadiance` of angular
// radius sunRadiusDeg towards `sun`.
Image sunnySky(int height, const glm::vec3& sun, double sunRadiusDeg, float sunRadiance) {
    const double cosSun = std::cos(sunRadiusDeg * kPi / 180.0);
    return test::latLongImage(2 * height, height, [&](const glm::vec3& d) {
        if (glm::dot(glm::dvec3(d), glm::dvec3(sun)) >= cosSun) return glm::vec3(sunRadiance, 0.95f * sunRadiance, 0.85f * sunRadiance);
        return d.y >= 0.0f ? glm::mix(glm::vec3(0.2f, 0.4f, 0.9f), glm::vec3(0.9f, 0.95f, 1.0f), (1.0f - d.y) * (1.0f - d.y))
                           : glm::vec3(0.2f, 0.16f, 0.1f);
    });
}

double relative(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) / glm::length(b); }

LightExtractionSettings oneLight() {
    LightExtractionSettings settings;
    settings.maxSolidAngleSr = 0.2f;
    return settings;
}

}  // namespace

// For a 3-degree sun low in the sky, across the longitude seam (azimuth 0 is
// u = 0) and over the north pole: one light, towards the disc's centre, of
// the disc's texels' solid angle, and
//   - on a plane facing it: light + remainder = the map, to 1e-5 (float
//     rounding of a sum over 131k texels; leaving out the fill that replaces
//     the sun in the remainder adds the sky behind the sun twice, 2e-4);
//   - over the sphere, sum L d omega: remainder + the light as a uniform disc
//     of its solid angle (irradiance x 2 / (1 + cos radius)) = the map, to the
//     goal's 1e-3;
//   - on every plane that sees the whole disc, to 1e-4: within that cone a
//     directional light is exact.
TEST(DominantLight, LightPlusRemainderIsTheMapWhereverTheSunIs) {
    constexpr int kHeight = 256;
    constexpr double kSunRadiusDeg = 1.5;
    struct Case {
        const char* name;
        glm::vec3 sun;
    } cases[] = {{"low sun", towards(45.0, 10.0)}, {"across the seam", towards(0.0, 30.0)}, {"over the pole", towards(20.0, 89.6)}};
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        const Image map = sunnySky(kHeight, c.sun, kSunRadiusDeg, 5000.0f);
        const EnvironmentSplit split = extractDominantLights(map, oneLight());
        ASSERT_EQ(split.lights.size(), 1u) << split.why;
        const ExtractedLight& light = split.lights.front();

        double discSolidAngle = 0.0;
        int discTexels = 0;
        for (int v = 0; v < kHeight; ++v)
            for (int u = 0; u < 2 * kHeight; ++u)
                if (map.at(u, v).r >= 5000.0f) {
                    discSolidAngle += texelSolidAngle(v, 2 * kHeight, kHeight);
                    ++discTexels;
                }
        EXPECT_EQ(light.texels, discTexels);
        EXPECT_NEAR(light.solidAngleSr / discSolidAngle, 1.0, 1e-4);
        // A quarter of a 0.7-degree texel: the centroid of the texels the disc covers.
        EXPECT_LT(glm::degrees(std::acos(std::min(1.0f, glm::dot(light.towardsLight, c.sun)))), 0.18f);
        // 2.7-3.3 degrees: the disc's texels cover its area to within the texels along its edge.
        EXPECT_NEAR(light.angularDiameterDeg, 2.0 * kSunRadiusDeg, 0.1 * 2.0 * kSunRadiusDeg);

        const glm::dvec3 facing(light.towardsLight);
        EXPECT_LT(relative(integrate(split.remainder, facing) + glm::dvec3(light.irradiance), integrate(map, facing)), 1e-5);
        const double radius = glm::radians(0.5 * double(light.angularDiameterDeg));
        const glm::dvec3 discFlux = glm::dvec3(light.irradiance) * (2.0 / (1.0 + std::cos(radius)));
        EXPECT_LT(relative(integrate(split.remainder, glm::dvec3(0.0)) + discFlux, integrate(map, glm::dvec3(0.0))), 1e-3);
        for (int i = 0; i < 24; ++i) {
            // Normals up to 80 degrees from the light: every texel of the disc is in front of them.
            const glm::dvec3 side = glm::normalize(glm::cross(facing, glm::dvec3(0.3, 0.5, 0.8)));
            const glm::dvec3 other = glm::cross(facing, side);
            const double tilt = glm::radians(80.0 * (i % 8) / 7.0), turn = 2.0 * kPi * i / 24.0;
            const glm::dvec3 n = std::cos(tilt) * facing + std::sin(tilt) * (std::cos(turn) * side + std::sin(turn) * other);
            const glm::dvec3 lit = integrate(split.remainder, n) + glm::dvec3(light.irradiance) * glm::dot(n, facing);
            EXPECT_LT(relative(lit, integrate(map, n)), 1e-4) << "normal " << i;
        }
        // The remainder holds the sky in the sun's place, no more than the sky around it.
        EXPECT_LT(light.fill.r, 1.0f);
        EXPECT_GT(light.fill.b, 0.2f);
    }
}

// A uniform map has no light to take out; nor does one whose bright part is
// a broad area (a cap of 26 degrees radius, 0.63 sr, above the 0.2 sr
// allowed; 100 against a mean of 6); a dim sun below the threshold stays
// too. Each says why.
TEST(DominantLight, NothingIsTakenWithoutACompactBrightRegion) {
    const Image uniform = test::latLongImage(64, 32, [](const glm::vec3&) { return glm::vec3(1.0f); });
    EnvironmentSplit split = extractDominantLights(uniform, oneLight());
    EXPECT_TRUE(split.lights.empty());
    EXPECT_NE(split.why.find("no texel reaches"), std::string::npos) << split.why;

    const Image broad = test::latLongImage(128, 64, [](const glm::vec3& d) { return glm::vec3(d.y > 0.9f ? 100.0f : 1.0f); });
    split = extractDominantLights(broad, oneLight());
    EXPECT_TRUE(split.lights.empty());
    EXPECT_NE(split.why.find("not a compact light"), std::string::npos) << split.why;

    // Beside that broad area, a small lamp less bright than it is the light taken out.
    const glm::vec3 lamp = towards(-30.0, -20.0);
    const Image broadAndLamp = test::latLongImage(256, 128, [&](const glm::vec3& d) {
        return glm::vec3(d.y > 0.9f ? 100.0f : glm::dot(d, lamp) > std::cos(glm::radians(4.0f)) ? 60.0f : 1.0f);
    });
    split = extractDominantLights(broadAndLamp, oneLight());
    ASSERT_EQ(split.lights.size(), 1u) << split.why;
    EXPECT_GT(glm::dot(split.lights.front().towardsLight, lamp), std::cos(glm::radians(0.5f)));

    const Image dimSun = sunnySky(64, towards(10.0, 40.0), 5.0, 3.0f);
    split = extractDominantLights(dimSun, oneLight());
    EXPECT_TRUE(split.lights.empty()) << "a sun of 3 is less than 8 x the sky's mean";
}

// The median weighs texels by solid angle: the rows near the poles hold many
// small texels. Bright (2) above |y| = 0.6 is 40% of the sphere but 59% of
// the rows: the median is the dim 1, where counting texels would say 2.
// The mean: 0.4 x 2 + 0.6 x 1 = 1.4, to the texels' share of the caps' edge.
TEST(DominantLight, MedianAndMeanLuminanceAreOverSolidAngle) {
    const Image map = test::latLongImage(128, 64, [](const glm::vec3& d) { return glm::vec3(std::abs(d.y) > 0.6f ? 2.0f : 1.0f); });
    EXPECT_FLOAT_EQ(medianLuminance(map), 1.0f);
    EXPECT_NEAR(meanLuminance(map), 1.4f, 0.01f);
}

TEST(DominantLight, ConeDiameterOfASolidAngle) {
    EXPECT_NEAR(coneAngularDiameterDeg(float(2.0 * kPi * (1.0 - std::cos(glm::radians(15.0))))), 30.0f, 1e-3f);
    EXPECT_NEAR(coneAngularDiameterDeg(float(4.0 * kPi)), 360.0f, 1e-3f);
}
