// SH irradiance that added light cannot darken (env/RingingFreeSh.h): a hot
// texel in a dim map, where nine plain coefficients ring negative on the far
// side and the clamp turns added light into lost light.
#include "env/RingingFreeSh.h"

#include "core/Luminance.h"
#include "env/DominantLight.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace dermis;

namespace {

// Normals spread evenly over the sphere (a Fibonacci lattice).
std::vector<glm::vec3> sphereNormals(int count) {
    std::vector<glm::vec3> normals;
    const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - 2.0f * (i + 0.5f) / count, r = std::sqrt(1.0f - y * y);
        normals.emplace_back(r * std::cos(golden * i), y, r * std::sin(golden * i));
    }
    return normals;
}

// The largest drop of the (clamped, as the shaders clamp) luminance of the
// irradiance from `before` to `after` over the normals, relative to `scale`.
float largestDarkening(const Sh9& before, const Sh9& after, float scale) {
    float worst = 0.0f;
    for (const glm::vec3& n : sphereNormals(2000)) {
        const float b = relativeLuminance(glm::max(shIrradiance(before, n), glm::vec3(0.0f)));
        const float a = relativeLuminance(glm::max(shIrradiance(after, n), glm::vec3(0.0f)));
        worst = std::max(worst, (b - a) / scale);
    }
    return worst;
}

Image withHotTexel(Image map, int u, int v, float radiance) {
    map.at(u, v) = glm::vec4(glm::vec3(radiance), 1.0f);
    return map;
}

}  // namespace

// The darkening the header allows: the unwindowed part of a texel's power,
// at most kShUnwindowedPowerFraction x 4 pi x the median of the map with the
// light added (added light can only raise the median), times the plain
// kernel's dip of 0.0396; plus float rounding (1e-5 of the median). With the
// median of the map before, a texel on the ground of a sky, whose median
// sits on the ground's edge, fails by 2.4 x.
static float allowedDarkening(const Image& map) {
    const float median = medianLuminance(map);
    return float(0.0396 * kShUnwindowedPowerFraction * 4.0 * 3.14159265358979 * median) + 1e-5f * median;
}

// One texel of 1000 in a uniform map of 0.5 at 8 x 4, 64 x 32 and 256 x 128,
// at the equator, near a pole and on the seam: no normal gets darker beyond
// the allowed 1.6e-4 of the map's irradiance pi x 0.5. Plain projection
// loses 20% to all of the map's light on the 8 x 4 and 64 x 32 maps
// (asserted, so that the test is seen to look where the ringing is); giving
// band 1 a window of 0.9, outside the non-negative set, darkens the 64 x 32
// map by 6%.
TEST(RingingFreeSh, AHotTexelNeverDarkensADimMap) {
    for (const int height : {4, 32, 128}) {
        const Image dim = test::latLongImage(2 * height, height, [](const glm::vec3&) { return glm::vec3(0.5f); });
        const Sh9 before = projectLatLongWithoutRinging(dim);
        for (const auto& [u, v] : {std::pair<int, int>{height / 2, height / 2}, {0, 0}, {2 * height - 1, height - 1}}) {
            SCOPED_TRACE(std::to_string(2 * height) + "x" + std::to_string(height) + " texel " + std::to_string(u) + "," +
                         std::to_string(v));
            const Image hot = withHotTexel(dim, u, v, 1000.0f);
            EXPECT_LE(largestDarkening(before, projectLatLongWithoutRinging(hot), 1.0f), allowedDarkening(hot));
            if (height <= 32 && v == height / 2)
                EXPECT_GT(largestDarkening(projectLatLong(dim), projectLatLong(hot), 3.14159265f * 0.5f), 0.2f);
        }
    }
}

// A bright texel on a non-uniform sky (no sun) may darken a normal only by
// the unwindowed part of its power (allowedDarkening), wherever it is and
// however bright.
TEST(RingingFreeSh, ABrightTexelOnASkyDarkensNoNormalBeyondTheBound) {
    const Image sky = test::latLongImage(256, 128, [](const glm::vec3& d) {
        return d.y >= 0.0f ? glm::mix(glm::vec3(0.2f, 0.4f, 0.9f), glm::vec3(0.9f, 0.95f, 1.0f), (1.0f - d.y) * (1.0f - d.y))
                           : glm::vec3(0.2f, 0.16f, 0.1f);
    });
    const Sh9 before = projectLatLongWithoutRinging(sky);
    for (const float radiance : {20.0f, 300.0f, 1e5f}) {
        for (const auto& [u, v] : {std::pair<int, int>{40, 60}, {200, 20}, {0, 100}}) {
            SCOPED_TRACE(std::to_string(radiance) + " at " + std::to_string(u) + "," + std::to_string(v));
            const Image hot = withHotTexel(sky, u, v, radiance);
            EXPECT_LE(largestDarkening(before, projectLatLongWithoutRinging(hot), 1.0f), allowedDarkening(hot));
        }
    }
}

// Maps without hot texels are projected exactly as before (a sky's texels
// carry less than 1/1024 of 4 pi x the median each at 256 x 128), and a
// uniform map gives pi L everywhere (1e-4: the band-2 quadrature at 256 x 128).
TEST(RingingFreeSh, SmoothMapsAreProjectedAsBefore) {
    const Image sky = test::latLongImage(256, 128, [](const glm::vec3& d) { return glm::vec3(0.5f + 0.4f * d.y, 0.6f, 0.7f - 0.2f * d.x); });
    const Sh9 plain = projectLatLong(sky), safe = projectLatLongWithoutRinging(sky);
    for (int i = 0; i < kShCoefficients; ++i)
        EXPECT_LT(glm::length(plain.coefficients[size_t(i)] - safe.coefficients[size_t(i)]), 1e-6f) << i;
    const Image uniform = test::latLongImage(256, 128, [](const glm::vec3&) { return glm::vec3(2.0f); });
    for (const glm::vec3& n : sphereNormals(50))
        EXPECT_NEAR(shIrradiance(projectLatLongWithoutRinging(uniform), n).g / (3.14159265f * 2.0f), 1.0f, 1e-4f);
}
