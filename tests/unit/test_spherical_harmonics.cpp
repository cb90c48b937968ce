// Nine-coefficient spherical harmonics of environment light
// (env/SphericalHarmonics.h) against closed forms.
#include "env/SphericalHarmonics.h"

#include "TestSupport.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>

using namespace dermis;

namespace {

constexpr float kPi = 3.14159265358979f;

using test::latLongImage;

// The clamped cosine about `axis`: max(0, d . axis).
std::function<glm::vec3(const glm::vec3&)> lobe(const glm::vec3& axis) {
    return [axis](const glm::vec3& d) { return glm::vec3(std::max(0.0f, glm::dot(d, axis))); };
}

TEST(SphericalHarmonics, TexelSolidAnglesCoverTheSphere) {
    double total = 0.0;
    for (int v = 0; v < 64; ++v) total += 128.0 * latLongTexelSolidAngle(v, 128, 64);
    EXPECT_NEAR(total, 4.0 * M_PI, 1e-4);
}

// The goal: a constant environment L gives irradiance pi L everywhere, to 1e-4 relative.
TEST(SphericalHarmonics, ConstantEnvironmentGivesPiTimesItsRadiance) {
    const glm::vec3 radiance(1.0f, 0.5f, 0.25f);
    const Sh9 sh = projectLatLong(latLongImage(256, 128, [&](const glm::vec3&) { return radiance; }));
    for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f))}) {
        const glm::vec3 e = shIrradiance(sh, n);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c] / (kPi * radiance[c]), 1.0f, 1e-4f) << "channel " << c;
    }
    // Bands 1 and 2 of a constant are zero. The texel-centre quadrature of
    // the band-2 functions is off by O(1/H^2): 3e-3 at 64 x 32, 2e-4 at 256 x 128.
    for (int i = 1; i < kShCoefficients; ++i) EXPECT_LT(glm::length(sh.coefficients[size_t(i)]), 3e-4f) << i;
}

// The clamped cosine about +Z projects onto Y00, Y10 and Y20 only, with
//   L00 = 0.282095 pi, L10 = 0.488603 (2 pi / 3), L20 = 0.315392 (pi / 2)
// (integrals of c, c^2 and c (3c^2 - 1) over the hemisphere). Within 1% at
// 256 x 128; the band-limited irradiance at +Z follows from these in closed
// form: pi L00 Y00 + (2 pi / 3) L10 Y10(z) + (pi / 4) L20 Y20(z).
TEST(SphericalHarmonics, ClampedCosineLobeMatchesItsClosedForm) {
    const Sh9 sh = projectLatLong(latLongImage(256, 128, lobe(glm::vec3(0, 0, 1))));
    const float expected[kShCoefficients] = {0.282095f * kPi, 0, 0.488603f * 2.0f * kPi / 3.0f, 0, 0, 0,
                                             0.315392f * kPi / 2.0f, 0, 0};
    for (int i = 0; i < kShCoefficients; ++i) {
        if (expected[i] != 0.0f)
            EXPECT_NEAR(sh.coefficients[size_t(i)].r / expected[i], 1.0f, 0.01f) << "coefficient " << i;
        else
            EXPECT_LT(std::abs(sh.coefficients[size_t(i)].r), 0.01f * expected[0]) << "coefficient " << i;
    }
    const float closedForm = kPi * expected[0] * 0.282095f + 2.0f * kPi / 3.0f * expected[2] * 0.488603f +
                             kPi / 4.0f * expected[6] * 0.315392f * 2.0f;
    EXPECT_NEAR(shIrradiance(sh, glm::vec3(0, 0, 1)).r / closedForm, 1.0f, 0.01f);
}

// Rotating the coefficients equals projecting the rotated environment (an
// independent computation), and irradiance turns with the light.
TEST(SphericalHarmonics, RotatedCoefficientsEqualTheRotatedEnvironmentsProjection) {
    const glm::mat3 rotation(glm::rotate(glm::mat4(1.0f), glm::radians(37.0f), glm::normalize(glm::vec3(0.4f, 1.0f, -0.3f))));
    const glm::vec3 axis = glm::normalize(glm::vec3(0.2f, 0.5f, 0.8f));
    const Sh9 original = projectLatLong(latLongImage(256, 128, lobe(axis)));
    const Sh9 rotated = rotateSh(original, rotation);
    const Sh9 reprojected = projectLatLong(latLongImage(256, 128, lobe(rotation * axis)));
    for (int i = 0; i < kShCoefficients; ++i)
        EXPECT_NEAR(rotated.coefficients[size_t(i)].r, reprojected.coefficients[size_t(i)].r, 2e-3f) << "coefficient " << i;
    for (const glm::vec3& n : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(1, -1, 0.5f))})
        EXPECT_NEAR(shIrradiance(rotated, rotation * n).r, shIrradiance(original, n).r, 1e-5f);
    // A rotation by the identity changes nothing; by 360 degrees about any axis, neither.
    const Sh9 same = rotateSh(original, glm::mat3(1.0f));
    for (int i = 0; i < kShCoefficients; ++i)
        EXPECT_NEAR(same.coefficients[size_t(i)].g, original.coefficients[size_t(i)].g, 1e-6f);
}

// A single bright texel: its coefficients are its radiance x Y(direction) x its solid angle.
TEST(SphericalHarmonics, SingleBrightTexelProjectsAsItsDirection) {
    const int width = 32, height = 16, u = 5, v = 11;
    Image map = latLongImage(width, height, [](const glm::vec3&) { return glm::vec3(0.0f); });
    map.at(u, v) = glm::vec4(1000.0f, 0.0f, 0.0f, 1.0f);
    const Sh9 sh = projectLatLong(map);
    const glm::vec3 d = latLongDirection(u, v, width, height);
    const float omega = latLongTexelSolidAngle(v, width, height);
    const auto y = shBasis(d);
    for (int i = 0; i < kShCoefficients; ++i)
        EXPECT_NEAR(sh.coefficients[size_t(i)].r, 1000.0f * y[size_t(i)] * omega, 1e-4f) << "coefficient " << i;
}

}  // namespace
