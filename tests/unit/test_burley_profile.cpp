// Burley's normalized diffusion and its six-Gaussian fit (docs/screen-space.md,
// "Burley's normalized diffusion"; Christensen & Burley 2015).
#include "sss/BurleyProfile.h"

#include "AnalyticEdge.h"
#include "Quadrature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>

using namespace dermis;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Skin1 of Jensen et al. 2001 table 2 (sigma_s' = (0.74, 0.88, 1.01) /mm, sigma_a = (0.032,
// 0.17, 0.48) /mm, eta = 1.3): the mean free path l = 1 / (sigma_s' + sigma_a) and, as the
// surface albedo, the dipole's closed-form total diffuse reflectance (Jensen et al. 2001 §2.4),
// rounded to 4 digits; d = l / s(A) = (0.739, 0.324, 0.176) mm.
const BurleyParameters kSkin1{{0.4360f, 0.2273f, 0.1310f}, {1.2953f, 0.9524f, 0.6711f}};

// Bounds for the six-Gaussian fit, a little above what it measures (see the docs).
constexpr double kFitRelativeL2Bound = 0.2;
constexpr double kFitCdfBound = 0.02;

using quadrature::simpson;

// The integral of 2 pi r R(r) from 0 to radiusMm, with r = e^t (R ~ 1/r near 0 and the two
// exponentials span a factor 3 in scale); the part below 1e-12 d, about 3e-13, is left out.
double numericalCdf(double radiusMm, double dMm) {
    return simpson([&](double t) {
        const double r = std::exp(t);
        return 2.0 * kPi * r * r * burleyRadialProfile(r, dMm);
    }, std::log(1e-12 * dMm), std::log(radiusMm), 20000);
}

void expectFitWithinBounds(const BurleyParameters& parameters, const char* label) {
    Result<DiffusionProfile> fit = fitBurleyGaussians(parameters);
    ASSERT_TRUE(fit.ok()) << fit.error().message();
    ASSERT_EQ(fit->size(), 6u);
    glm::dvec3 sums(0.0);
    for (const ProfileGaussian& g : fit->gaussians()) {
        for (int c = 0; c < 3; ++c) EXPECT_GE(g.weight[c], 0.0f) << label;
        sums += glm::dvec3(g.weight);
    }
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sums[c], 1.0, 1e-6) << label << " channel " << c;
    const BurleyFitError error = measureBurleyFit(parameters, *fit);
    std::printf("%s: variances %.5g..%.5g mm^2 (ratio %.4g); relative L2 of 2 pi r R (%.4f, %.4f, %.4f), "
                "largest CDF error (%.5f, %.5f, %.5f)\n",
                label, fit->gaussians().front().varianceMm2, fit->gaussians().back().varianceMm2,
                fit->gaussians()[1].varianceMm2 / fit->gaussians()[0].varianceMm2, error.relativeL2.x, error.relativeL2.y,
                error.relativeL2.z, error.largestCdfError.x, error.largestCdfError.y, error.largestCdfError.z);
    for (int c = 0; c < 3; ++c) {
        EXPECT_LT(error.relativeL2[c], kFitRelativeL2Bound) << label << " channel " << c;
        EXPECT_LT(error.largestCdfError[c], kFitCdfBound) << label << " channel " << c;
    }
}

}  // namespace

TEST(BurleyProfile, ScalingFactorIsChristensenBurleySearchlightFit) {
    EXPECT_NEAR(burleyScalingFactor(0.8), 1.05, 1e-12);
    EXPECT_NEAR(burleyScalingFactor(1.0), 1.85 - 1.0 + 7.0 * 0.008, 1e-12);
    EXPECT_NEAR(burleyScalingFactor(0.0), 1.85 + 7.0 * 0.512, 1e-12);
    const glm::dvec3 d = burleyShapeDistanceMm({{0.8f, 1.0f, 0.0f}, {2.1f, 1.0f, 1.0f}});
    EXPECT_NEAR(d.x, 2.1 / 1.05, 1e-6);
    EXPECT_NEAR(d.y, 1.0 / 0.906, 1e-6);
    EXPECT_NEAR(d.z, 1.0 / 5.434, 1e-6);
}

TEST(BurleyProfile, NormalisedProfileIntegratesToOne) {
    for (double d : {0.05, 0.3, 1.0, 4.0}) EXPECT_NEAR(numericalCdf(200.0 * d, d), 1.0, 1e-9) << "d " << d;
    // Per channel through the parameters, out to 200 mm.
    const glm::dvec3 d = burleyShapeDistanceMm(kSkin1);
    for (int c = 0; c < 3; ++c) {
        const double integral = simpson([&](double t) {
            const double r = std::exp(t);
            return 2.0 * kPi * r * r * burleyRadialProfile(kSkin1, r)[c];
        }, std::log(1e-12), std::log(200.0), 20000);
        EXPECT_NEAR(integral, 1.0, 1e-9) << "channel " << c << " d " << d[c];
    }
}

TEST(BurleyProfile, CdfMatchesNumericalIntegration) {
    for (double d : {0.05, 0.3, 1.0, 4.0})
        for (double radiusInD : {0.001, 0.01, 0.1, 0.5, 1.0, 2.0, 3.0, 7.0, 20.0, 60.0})
            EXPECT_NEAR(burleyRadialCdf(radiusInD * d, d), numericalCdf(radiusInD * d, d), 1e-9)
                << "d " << d << " r/d " << radiusInD;
    EXPECT_EQ(burleyRadialCdf(0.0, 1.0), 0.0);
    EXPECT_EQ(burleyRadialCdf(-1.0, 1.0), 0.0);
    EXPECT_EQ(burleyRadialCdf(std::numeric_limits<double>::infinity(), 1.0), 1.0);
}

TEST(BurleyProfile, SixGaussianFitOfSkinIsWithinBounds) { expectFitWithinBounds(kSkin1, "skin1"); }

TEST(BurleyProfile, SixGaussianFitOfOtherParametersIsWithinBounds) {
    expectFitWithinBounds({{0.8f, 0.6f, 0.5f}, {1.0f, 0.4f, 0.25f}}, "albedo (0.8, 0.6, 0.5), l (1, 0.4, 0.25) mm");
    expectFitWithinBounds({{0.5f, 0.5f, 0.5f}, {1.0f, 1.0f, 1.0f}}, "grey, l 1 mm");
}

TEST(BurleyProfile, GaussianCdfOfTheFitIsItsRadialProfileIntegrated) {
    Result<DiffusionProfile> fit = fitBurleyGaussians(kSkin1);
    ASSERT_TRUE(fit.ok()) << fit.error().message();
    for (double r : {0.01, 0.1, 0.5, 2.0, 8.0}) {
        for (int c = 0; c < 3; ++c) {
            const double integral = simpson([&](double t) {
                const double x = std::exp(t);
                return 2.0 * kPi * x * x * double(fit->radialProfile(float(x))[c]);
            }, std::log(1e-9), std::log(r), 20000);
            EXPECT_NEAR(gaussianRadialCdf(*fit, r)[c], integral, 1e-6) << "r " << r << " channel " << c;
        }
    }
}

// The edge response's closed form (AnalyticEdge.h) against two independent computations:
// - the defining integral over rings, dark(a) = int_a^inf R(r) 2 r acos(a/r) dr with r = a cosh t,
//   by Simpson's rule (to r = 200 d; 40000 intervals reach 1e-9 there);
// - the Bickley function's derivative, d/dx Ki_1(x) = -K_0(x) (Abramowitz & Stegun 1964,
//   11.2.12), against std::cyl_bessel_k, with Ki_1(0) = pi/2.
// Bounds: 1e-9 for the integral (the Simpson sum's own error), 1e-8 relative for the central
// difference (step 1e-6: truncation h^2 K_0''/6 K_0, 4e-10 at x = 0.01; rounding about 1e-10). Broken on
// purpose: dropping the e^(-r/3d) term's factor 3 is off by 0.25 at x = 0 and fails both; a
// trapezoid step of 1.0 instead of 0.1 is off by up to 9e-5 and fails the first.
TEST(BurleyProfile, EdgeResponseClosedFormMatchesItsIntegral) {
    for (double d : {0.176, 0.739}) {
        for (double x : {-6.0, -1.5, -0.3, -0.02, 0.001, 0.05, 0.4, 2.0}) {
            const double a = std::fabs(x);
            const double dark = simpson([&](double t) {
                const double r = a * std::cosh(t);
                return 2.0 * r * burleyRadialProfile(r, d) * std::acos(1.0 / std::cosh(t)) * a * std::sinh(t);
            }, 0.0, std::acosh(200.0 * d / a), 40000);
            EXPECT_NEAR(test::burleyEdgeResponse(x, d), x < 0.0 ? dark : 1.0 - dark, 1e-9) << "x " << x << " d " << d;
        }
    }
    EXPECT_NEAR(test::bickleyKi1(0.0), kPi / 2.0, 1e-15);
    EXPECT_NEAR(test::burleyEdgeResponse(0.0, 0.5), 0.5, 1e-15);
    for (double x : {0.01, 0.1, 1.0, 5.0, 20.0}) {
        constexpr double h = 1e-6;
        const double derivative = (test::bickleyKi1(x + h) - test::bickleyKi1(x - h)) / (2.0 * h);
        const double k0 = std::cyl_bessel_k(0.0, x);
        EXPECT_NEAR(-derivative / k0, 1.0, 1e-8) << "x " << x;
    }
}

TEST(BurleyProfile, FitEdgeResponseIsWithinHalfItsCdfError) {
    Result<DiffusionProfile> fit = fitBurleyGaussians(kSkin1);
    ASSERT_TRUE(fit.ok()) << fit.error().message();
    const BurleyFitError error = measureBurleyFit(kSkin1, *fit);
    const glm::dvec3 d = burleyShapeDistanceMm(kSkin1);
    glm::dvec3 largest(0.0);
    for (double x : {-4.0, -2.0, -1.0, -0.5, -0.2, -0.1, -0.05, -0.02, -0.005, 0.0, 0.005, 0.02, 0.05, 0.1, 0.3, 1.0, 3.0})
        for (int c = 0; c < 3; ++c) {
            const double difference = std::fabs(double(fit->edgeResponse(float(x))[c]) - test::burleyEdgeResponse(x, d[c]));
            EXPECT_LE(difference, error.largestCdfError[c] / 2.0 + 1e-6) << "x " << x << " channel " << c;
            largest[c] = std::fmax(largest[c], difference);
        }
    std::printf("skin1: largest edge-response error (%.5f, %.5f, %.5f) at the sampled x\n", largest.x, largest.y, largest.z);
}

TEST(BurleyProfile, FitRejectsBadInputs) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    auto message = [](const BurleyParameters& p, int n) {
        Result<DiffusionProfile> fit = fitBurleyGaussians(p, n);
        return fit.ok() ? std::string("(accepted)") : fit.error().message();
    };
    EXPECT_EQ(message({{1.2f, 0.5f, 0.5f}, glm::vec3(1.0f)}, 6), "Burley parameters: the red albedo is 1.200000; it must be in [0, 1]");
    EXPECT_NE(message({{0.5f, nan, 0.5f}, glm::vec3(1.0f)}, 6).find("the green albedo is nan"), std::string::npos);
    EXPECT_EQ(message({glm::vec3(0.5f), {1.0f, 1.0f, 0.0f}}, 6),
              "Burley parameters: the blue scattering distance is 0.000000 mm; it must be finite and > 0");
    EXPECT_NE(message({glm::vec3(0.5f), {std::numeric_limits<float>::infinity(), 1.0f, 1.0f}}, 6).find("must be finite and > 0"),
              std::string::npos);
    EXPECT_EQ(message({glm::vec3(0.5f), glm::vec3(1.0f)}, 0), "Burley fit: 0 Gaussians; the fit takes 1 to 8");
    EXPECT_EQ(message({glm::vec3(0.5f), glm::vec3(1.0f)}, 9), "Burley fit: 9 Gaussians; the fit takes 1 to 8");
    EXPECT_EQ(message({glm::vec3(0.5f), glm::vec3(1.0f)}, 1), "(accepted)");
}

