// Pre-integrated shadows (sss/PreintegratedShadow.h) against closed forms and an independent
// brute-force quadrature: a hard edge scattered by skin is sum_i w_i Phi(x / sigma_i); a soft
// (PCSS) edge is the profile's marginal convolved with the disc-segment penumbra, which the test
// integrates on a fine uniform grid in t (not the implementation's Gauss-Legendre in phi); the
// coverage c of the measuring disc locates x through the disc-segment area (support/PenumbraEdge.h,
// the shadow tests' closed form), inverted by bisection there.
#include "PenumbraEdge.h"
#include "sss/PreintegratedShadow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

// sigma: the widest standard deviation of the Gaussians that carry at least 10% of a channel
// (skin: 1.41 mm, the fifth; the sixth, 2.72 mm, carries 7.8% of red).
double widestSigmaMm(const DiffusionProfile& profile) {
    double widest = 0.0;
    for (const ProfileGaussian& g : profile.gaussians()) {
        if (g.weight.r >= 0.1f || g.weight.g >= 0.1f || g.weight.b >= 0.1f) widest = std::max(widest, std::sqrt(double(g.varianceMm2)));
    }
    return widest;
}

// x across the edge (mm) that coverage c of the disc of radius 2 sigma sqrt(1 + q^2) means.
double edgeOffsetMm(const DiffusionProfile& profile, double c, double q) {
    return 2.0 * widestSigmaMm(profile) * std::sqrt(1.0 + q * q) * test::discSegmentOffset(c);
}

// sum_i w_i integral N(x - t; sigma_i) A(t / h) dt on a uniform grid of 400,001 points over the
// Gaussians' and the penumbra's support (trapezoid rule; its kinks at t = +-h cost O(dt^1.5)).
glm::dvec3 bruteForceSoftEdge(const DiffusionProfile& profile, double x, double hMm) {
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) {
        const double sigma = std::sqrt(double(g.varianceMm2));
        const double lo = std::min(-hMm, x - 10.0 * sigma), hi = std::max(hMm, x + 10.0 * sigma);
        const int n = 400000;
        const double dt = (hi - lo) / n;
        double integral = 0.0;
        for (int k = 0; k <= n; ++k) {
            const double t = lo + k * dt;
            const double u = (x - t) / sigma;
            const double f = std::exp(-0.5 * u * u) / (sigma * std::sqrt(2.0 * kPi)) * test::discSegmentVisibility(t / hMm);
            integral += (k == 0 || k == n ? 0.5 : 1.0) * f * dt;
        }
        // Past hi the penumbra is lit: the Gaussian's tail beyond hi.
        integral += 0.5 * std::erfc((hi - x) / (sigma * std::sqrt(2.0)));
        sum += glm::dvec3(g.weight) * integral;
    }
    return sum;
}

double largestError(const glm::vec4& got, const glm::dvec3& rgb, double alpha) {
    return std::max({std::fabs(got.r - rgb.r), std::fabs(got.g - rgb.g), std::fabs(got.b - rgb.b), std::fabs(got.a - alpha)});
}

}  // namespace

// A delta light (q = 0): V is a step and skin scatters it to sum_i w_i Phi(x / sigma_i), in double
// precision on both sides; the bound, 1e-6, is the float the result is returned in.
// Measured: 1.9e-7. Broken on purpose: the disc's radius taken as 2.1 sigma (k x 1.05) gives
// 1.0e-2; each sigma_i x 1.05, 1.0e-2; the widest Gaussian dropped, 6.5e-2. All fail.
TEST(PreintegratedShadow, HardEdgeIsTheProfileMarginal) {
    const DiffusionProfile& profile = skinProfile();
    double worst = 0.0;
    for (int i = 1; i < 100; ++i) {
        const double c = i / 100.0;
        const double x = edgeOffsetMm(profile, c, 0.0);
        glm::dvec3 expected(0.0);
        for (const ProfileGaussian& g : profile.gaussians())
            expected += glm::dvec3(g.weight) * (0.5 * std::erfc(-x / (std::sqrt(double(g.varianceMm2)) * std::sqrt(2.0))));
        const double step = x > 0.0 ? 1.0 : 0.0;
        worst = std::max(worst, largestError(preintegratedShadow(profile, float(c), 0.0f), expected, step));
    }
    std::printf("[ measured ] hard edge: %.2e\n", worst);
    EXPECT_LT(worst, 1e-6);
}

// A soft light: q = h / (2 sigma) from 0.1 (a small lamp) to 4 (a penumbra 16 sigma wide, where
// the scattering hardly shows). The brute force's own error is ~1e-8 (halving its step changes
// it by that); the implementation's 64 Gauss-Legendre nodes in phi hold it to 1e-9. Bound 1e-6,
// float rounding. Measured: 6.9e-8. Broken on purpose: the penumbra's half-width taken as
// 2.1 q sigma instead of 2 q sigma gives 1.5e-2; the phi substitution's Jacobian (h cos phi)
// dropped, 2.2; the disc's radius x 1.05, 1.6e-2. All fail.
TEST(PreintegratedShadow, SoftEdgeMatchesABruteForceConvolution) {
    const DiffusionProfile& profile = skinProfile();
    const double sigma = widestSigmaMm(profile);
    double worst = 0.0;
    for (double q : {0.1, 0.5, 1.0, 4.0}) {
        for (double c : {0.02, 0.2, 0.45, 0.5, 0.7, 0.93, 0.99}) {
            const double x = edgeOffsetMm(profile, c, q);
            const double h = 2.0 * q * sigma;
            const glm::dvec3 expected = bruteForceSoftEdge(profile, x, h);
            worst = std::max(worst, largestError(preintegratedShadow(profile, float(c), float(q)), expected, test::discSegmentVisibility(x / h)));
        }
    }
    std::printf("[ measured ] soft edge: %.2e\n", worst);
    EXPECT_LT(worst, 1e-6);
}

// By symmetry the disc half lit puts the receiver on the edge, where the scattered light and the
// light's own penumbra are both exactly half, for every channel and penumbra. Bound: float rounding.
TEST(PreintegratedShadow, HalfCoverageIsHalfLight) {
    for (float q : {0.0f, 0.3f, 3.0f, 30.0f}) {
        const glm::vec4 s = preintegratedShadow(skinProfile(), 0.5f, q);
        EXPECT_NEAR(s.r, 0.5, 1e-6) << q;
        EXPECT_NEAR(s.g, 0.5, 1e-6) << q;
        EXPECT_NEAR(s.b, 0.5, 1e-6) << q;
        // A delta light's own visibility (q = 0) is a step, undefined on the edge itself.
        if (q > 0.0f) EXPECT_NEAR(s.a, 0.5, 1e-6) << q;
    }
}

// Red scatters furthest: on the dark side of a hard edge it keeps more light than green and blue,
// on the lit side it loses more; the ends read exactly 0 and 1 (the disc wholly shadowed or lit).
// Coverage 0.4 lies 0.36 mm into skin's shadow (the disc's radius is 2 x 1.41 mm), where red keeps
// about a quarter of the lit level (sum_i w_i Phi(-0.36 / sigma_i)) and blue far less.
TEST(PreintegratedShadow, RedBleedsIntoTheShadow) {
    const glm::vec4 dark = preintegratedShadow(skinProfile(), 0.4f, 0.0f);
    const glm::vec4 lit = preintegratedShadow(skinProfile(), 0.6f, 0.0f);
    EXPECT_GT(dark.r, dark.g);
    EXPECT_GT(dark.r, dark.b);
    EXPECT_GT(dark.r, 0.05f);
    EXPECT_EQ(dark.a, 0.0f);
    EXPECT_LT(lit.r, lit.g);
    EXPECT_EQ(lit.a, 1.0f);
    EXPECT_EQ(preintegratedShadow(skinProfile(), 0.0f, 1.0f), glm::vec4(0.0f));
    EXPECT_EQ(preintegratedShadow(skinProfile(), 1.0f, 1.0f), glm::vec4(1.0f));
    EXPECT_EQ(preintegratedShadow(skinProfile(), std::numeric_limits<float>::quiet_NaN(), 1.0f), glm::vec4(0.0f));
}

// The table at its texel centres (c_i = i / 63, q_j = y_j / (1 - y_j)) is the direct value; the
// bound is float rounding of the two paths. Between centres the lookup is bilinear: the test
// checks that a value halfway between two coverage centres lies between them. Measured: 2.4e-7.
// Broken on purpose: the rows built at q = y instead of y / (1 - y) fails both checks.
TEST(PreintegratedShadow, TableHoldsTheDirectValueAtItsTexelCentres) {
    const PreintegratedShadowTable table = makePreintegratedShadowTable(skinProfile());
    ASSERT_EQ(table.texels.size(), size_t(table.coverages) * size_t(table.rows));
    double worst = 0.0;
    for (int j = 0; j < table.rows; ++j) {
        const double y = (j + 0.5) / table.rows;
        const float q = float(y / (1.0 - y));
        for (int i = 0; i < table.coverages; i += 3) {
            const float c = float(i) / float(table.coverages - 1);
            const glm::vec4 direct = preintegratedShadow(skinProfile(), c, q);
            worst = std::max(worst, largestError(table.at(c, q), glm::dvec3(direct), direct.a));
            if (i + 1 < table.coverages) {
                const float next = float(i + 1) / float(table.coverages - 1);
                const glm::vec4 between = table.at(0.5f * (c + next), q);
                const glm::vec4 right = preintegratedShadow(skinProfile(), next, q);
                EXPECT_GE(between.r, std::min(direct.r, right.r) - 1e-6f);
                EXPECT_LE(between.r, std::max(direct.r, right.r) + 1e-6f);
            }
        }
    }
    std::printf("[ measured ] table at texel centres: %.2e\n", worst);
    EXPECT_LT(worst, 2e-6);
}
