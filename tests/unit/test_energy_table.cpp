// Energy conservation between the KS specular lobe and the diffuse term (Chappuis 2011 §2.3, §2.6).
#include "brdf/EnergyTable.h"

#include "brdf/BeckmannTable.h"
#include "render/GpuEnvironment.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <random>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

glm::vec3 viewAt(float cosTheta) { return {std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta}; }

// Brute force: 2 pi times the mean of ksSpecular over directions uniform in solid angle,
// jittered-stratified in (cos theta_l, phi).
double monteCarloAlbedo(float cosTheta, float m, int strata) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const glm::vec3 n(0.0f, 0.0f, 1.0f), v = viewAt(cosTheta);
    double sum = 0.0;
    for (int i = 0; i < strata; ++i)
        for (int j = 0; j < strata; ++j) {
            const double mu = (i + jitter(rng)) / strata;
            const double phi = 2.0 * kPi * (j + jitter(rng)) / strata;
            const double sinTheta = std::sqrt(1.0 - mu * mu);
            const glm::vec3 l(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(mu));
            sum += double(ksSpecular(n, l, v, m));
        }
    return 2.0 * kPi * sum / (double(strata) * strata);
}

}  // namespace

TEST(EnergyTable, KsSpecularIsChappuisListing25) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 l = glm::normalize(glm::vec3(0.3f, 0.2f, 0.9f));
    const glm::vec3 v = glm::normalize(glm::vec3(-0.5f, 0.1f, 0.7f));
    const float m = 0.3f;
    const glm::vec3 h = l + v;
    const glm::vec3 H = glm::normalize(h);
    const double nDotH = glm::dot(n, H);
    const double tan2 = (1.0 - nDotH * nDotH) / (nDotH * nDotH);
    const double pH = std::exp(-tan2 / (m * m)) / (m * m * std::pow(nDotH, 4.0));
    const double base = 1.0 - glm::dot(v, H);
    const double fresnel = std::pow(base, 5.0) + 0.028 * (1.0 - std::pow(base, 5.0));
    const double expected = pH * fresnel / glm::dot(h, h) * glm::dot(n, l);
    EXPECT_NEAR(ksSpecular(n, l, v, m), expected, 1e-5 * expected);
    EXPECT_NEAR(beckmannPH(float(nDotH), m), pH, 1e-4 * pH);
}

TEST(EnergyTable, KsSpecularIsZeroBelowTheHorizonAndAlwaysFinite) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f), v = viewAt(0.6f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(ksSpecular(n, glm::vec3(0.0f, 0.6f, -0.8f), v, 0.3f), 0.0f);
    EXPECT_EQ(ksSpecular(n, glm::vec3(1.0f, 0.0f, 0.0f), v, 0.3f), 0.0f);  // N.L = 0
    EXPECT_EQ(ksSpecular(n, -v, v, 0.3f), 0.0f);                          // L = -V: |L + V| = 0
    const glm::vec3 mirror(-v.x, -v.y, v.z);
    for (float m : {0.0f, 1e-6f, 0.3f, 1.0f, 100.0f, nan, std::numeric_limits<float>::infinity()})
        EXPECT_TRUE(std::isfinite(ksSpecular(n, mirror, v, m))) << m;
    EXPECT_EQ(ksSpecular(n, glm::vec3(nan), v, 0.3f), 0.0f);
    EXPECT_TRUE(std::isfinite(ksSpecular(n, mirror, glm::vec3(nan), 0.3f)));
    // The lobe peaks in the mirror direction, at P_H = 1/m^2 and F = F0.
    EXPECT_NEAR(ksSpecular(n, n, n, 0.3f), 1.0f / 0.09f * 0.028f / 4.0f, 1e-5f);
}

TEST(EnergyTable, KsBrdfIsReciprocal) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    const glm::vec3 a = glm::normalize(glm::vec3(0.4f, -0.2f, 0.6f)), b = glm::normalize(glm::vec3(-0.3f, 0.5f, 0.8f));
    for (float m : {0.1f, 0.3f, 0.7f})
        EXPECT_NEAR(ksSpecular(n, a, b, m) / glm::dot(n, a), ksSpecular(n, b, a, m) / glm::dot(n, b), 1e-5f) << m;
}

TEST(EnergyTable, QuadratureHasConverged) {
    // The default rule against finer ones, including near grazing where the lobe is cut by the horizon.
    const RhoDtQuadrature fine{48, 48, 12}, finer{96, 96, 16};
    double worstOnTable = 0.0;
    for (int j = 0; j < kEnergyTableSize; j += 3)
        for (int i = 0; i < kEnergyTableSize; i += 3) {
            const float c = float(i) / (kEnergyTableSize - 1), m = float(j) / (kEnergyTableSize - 1);
            worstOnTable = std::fmax(worstOnTable, std::fabs(ksDirectionalAlbedo(c, m) - ksDirectionalAlbedo(c, m, fine)));
        }
    EXPECT_LT(worstOnTable, 2.5e-4);
    double worst = 0.0;
    for (float m : {0.0f, 0.02f, 0.1f, 0.3f, 0.6f, 1.0f})
        for (float c : {0.0f, 1e-4f, 1e-3f, 0.005f, 0.02f, 0.1f, 0.3f, 0.6f, 0.9f, 1.0f}) {
            const double reference = ksDirectionalAlbedo(c, m, finer);
            EXPECT_NEAR(ksDirectionalAlbedo(c, m, fine), reference, 1e-5) << "cos " << c << " m " << m;
            EXPECT_NEAR(ksDirectionalAlbedo(c, m), reference, 5e-4) << "cos " << c << " m " << m;
            worst = std::fmax(worst, std::fabs(ksDirectionalAlbedo(c, m) - reference));
        }
    std::printf("rhoDt default quadrature: worst |error| %.2e (%.2e at table points)\n", worst, worstOnTable);
}

TEST(EnergyTable, MatchesMonteCarlo) {
    for (auto [c, m] : {std::pair{1.0f, 0.3f}, {0.5f, 0.3f}, {0.2f, 0.5f}, {0.8f, 0.15f}, {0.35f, 1.0f}, {0.6f, 0.08f}}) {
        const double reference = monteCarloAlbedo(c, m, 1024);
        EXPECT_NEAR(rhoDt(c, m), reference, 1e-3) << "cos " << c << " m " << m;
        EXPECT_LT(reference, 1.0);  // so the clamp plays no part
    }
}

TEST(EnergyTable, SmoothLimitAtNormalIncidenceIsPiTimesF0) {
    // As m -> 0 the lobe is a mirror; Chappuis 2011's P_H integrates to pi there (not 1), and F = F0.
    EXPECT_NEAR(rhoDt(1.0f, 0.0f), kPi * 0.028, 1e-3);
    EXPECT_NEAR(rhoDt(1.0f, 0.01f), kPi * 0.028, 1e-3);
}

TEST(EnergyTable, RhoDtGrowsTowardGrazing) {
    // What holds for every m: from cos = 0.9 to grazing the lobe's albedo rises monotonically
    // (Fresnel wins over the part of the lobe lost below the horizon) and passes 1 near grazing,
    // where rhoDt clamps. Between 0.9 and normal incidence it never rises more than 1% above its
    // value at 0.9: for m < 0.5 it has a shallow minimum near cos = 0.93 and rises by up to
    // 0.7% (5e-4) towards cos = 1; rougher lobes keep falling.
    for (float m : {0.0f, 0.02f, 0.05f, 0.1f, 0.2f, 0.3f, 0.45f, 0.6f, 0.8f, 1.0f}) {
        double previous = ksDirectionalAlbedo(0.0f, m);
        for (int i = 1; i <= 90; ++i) {
            const float c = float(i) / 100.0f;
            const double albedo = ksDirectionalAlbedo(c, m);
            EXPECT_LT(albedo, previous) << "cos " << c << " m " << m;
            previous = albedo;
        }
        const double atPointNine = previous;
        for (int i = 91; i <= 100; ++i) {
            const double albedo = ksDirectionalAlbedo(float(i) / 100.0f, m);
            EXPECT_LT(albedo, 1.01 * atPointNine) << "m " << m;
            if (m >= 0.6f) { EXPECT_LT(albedo, previous) << "m " << m; }  // rough lobes keep falling
            previous = albedo;
        }
        EXPECT_GT(ksDirectionalAlbedo(0.0f, m), 5.0 * ksDirectionalAlbedo(1.0f, m)) << "m " << m;
    }
    EXPECT_GT(ksDirectionalAlbedo(0.0f, 0.3f), 1.0);
    EXPECT_EQ(rhoDt(0.0f, 0.3f), 1.0f);
}

TEST(EnergyTable, TableIsFiniteInUnitRangeAndSampledOnTexelCentres) {
    constexpr int kSize = kEnergyTableSize;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<float> table = makeEnergyTable(kSize);
    const double elapsedMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::printf("makeEnergyTable(%d): %.1f ms\n", kSize, elapsedMs);
    EXPECT_LT(elapsedMs, 1000.0);  // ~50 ms on two cores; generous for sanitizers and busy machines
    ASSERT_EQ(table.size(), size_t(kSize * kSize));
    for (size_t k = 0; k < table.size(); ++k) {
        ASSERT_TRUE(std::isfinite(table[k])) << k;
        ASSERT_GE(table[k], 0.0f);
        ASSERT_LE(table[k], 1.0f);
    }
    // Non-increasing in cos over [0, 0.9] (see RhoDtGrowsTowardGrazing).
    for (int j = 0; j < kSize; ++j)
        for (int i = 1; i * 10 <= (kSize - 1) * 9; ++i) ASSERT_LE(table[size_t(j * kSize + i)], table[size_t(j * kSize + i - 1)]) << i << " " << j;
    for (auto [i, j] : {std::pair{0, 0}, {63, 0}, {10, 19}, {32, 63}, {63, 63}})
        EXPECT_EQ(table[size_t(j * kSize + i)], rhoDt(float(i) / (kSize - 1), float(j) / (kSize - 1)));
    EXPECT_TRUE(makeEnergyTable(1).empty());
    EXPECT_EQ(makeEnergyTable(2).size(), 4u);
}

TEST(EnergyTable, RhoDtIsFiniteForAnyInput) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (float c : {nan, -inf, -1.0f, 0.0f, 0.5f, 1.0f, 2.0f, inf})
        for (float m : {nan, -inf, -1.0f, 0.0f, 1e-7f, 0.3f, 1.0f, 1e6f, inf}) {
            const float value = rhoDt(c, m);
            EXPECT_TRUE(std::isfinite(value)) << c << " " << m;
            EXPECT_GE(value, 0.0f);
            EXPECT_LE(value, 1.0f);
        }
}

// The environment's per-direction energy conservation (render/GpuEnvironment.h,
// rhoDtCubicFits) fits rho_dt(mu, m) with a cubic in mu, weighted by mu.
// Checked against rhoDt itself at 200 cosines per m (not the table the fit
// was made from): mu |cubic - rho_dt| stays under 0.03 (measured 0.006 to
// 0.022 over the rows checked, 0.013 at m = 0.3; the rise towards grazing at
// small m is what a cubic misses,
// weighted down by mu; rho_s = 0.18 turns 0.03 into 0.5% of the diffuse
// light at most). The cubic's mean 2 int c(mu) mu dmu equals the hemispherical
// average the "sh" diffuse uses, so both agree under a uniform map (the white
// furnace): within 1e-3 (the trapezoids against the exact integral;
// measured 5e-5). A quadratic instead of the cubic misses by 0.056 at
// m = 0.1 (measured with the same fit, one power fewer): it would fail.
TEST(EnergyTable, CubicFitsFollowRhoDtAndKeepItsAverage) {
    const std::vector<float> table = makeEnergyTable(kEnergyTableSize);
    const std::vector<glm::vec4> fits = rhoDtCubicFits(table, kEnergyTableSize);
    const std::vector<float> average = hemisphericalAverageAlbedo(table, kEnergyTableSize);
    ASSERT_EQ(fits.size(), size_t(kEnergyTableSize));
    for (int row : {6, 13, 19, 32, 45, 63}) {
        const float m = float(row) / (kEnergyTableSize - 1);
        const glm::vec4 c = fits[size_t(row)];
        double worst = 0.0;
        for (int i = 0; i < 200; ++i) {
            const double mu = (i + 0.5) / 200.0;
            const double cubic = c.x + mu * (c.y + mu * (c.z + mu * c.w));
            worst = std::max(worst, mu * std::abs(cubic - double(rhoDt(float(mu), m))));
        }
        const double mean = 2.0 * (c.x / 2.0 + c.y / 3.0 + c.z / 4.0 + c.w / 5.0);
        std::printf("m = %.3f: worst mu |cubic - rho_dt| %.4f; cubic's mean %.5f, average %.5f\n", m, worst, mean,
                    average[size_t(row)]);
        EXPECT_LT(worst, 0.03) << "m = " << m;
        EXPECT_NEAR(mean, average[size_t(row)], 1e-3) << "m = " << m;
    }
}
