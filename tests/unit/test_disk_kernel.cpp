// The disk technique's CPU kernel (sss/DiskKernel.h): normalised per channel,
// its cumulative weight follows the profile's radial CDF (Burley's exact
// profile for a Burley profile, the Gaussians' otherwise), deterministic.
#include "sss/DiskKernel.h"

#include "sss/BurleyProfile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

using namespace dermis;

namespace {

// The scenes' example Burley profile (content/scenes/README.md, "soft").
const BurleyParameters kSoft{{0.8f, 0.6f, 0.5f}, {1.0f, 0.4f, 0.25f}};

// Christensen & Burley 2015's normalised CDF with d = l / s(A), s(A) = 1.85 - A + 7 |A - 0.8|^3,
// written out here from the paper rather than taken from sss/BurleyProfile.h.
double paperBurleyCdf(const BurleyParameters& p, int c, double rMm) {
    const double a = p.albedo[c];
    const double s = 1.85 - a + 7.0 * std::pow(std::fabs(a - 0.8), 3.0);
    const double d = p.scatteringDistanceMm[c] / s;
    return 1.0 - 0.25 * std::exp(-rMm / d) - 0.75 * std::exp(-rMm / (3.0 * d));
}

// A sum of Gaussians' CDF from the profile's data: sum_i w_i (1 - exp(-r^2 / 2 v_i)).
double gaussianCdf(const DiffusionProfile& profile, int c, double rMm) {
    double sum = 0.0;
    for (const ProfileGaussian& g : profile.gaussians()) sum += g.weight[c] * (1.0 - std::exp(-rMm * rMm / (2.0 * g.varianceMm2)));
    return sum;
}

// The largest |W_c(r_k) - F_c(r_k)| over the samples, W_c(r_k) the kernel's weight below r_k
// plus half its own (the sample stands for its stratum, [F_m^-1(k/N), F_m^-1((k+1)/N)], and
// sits at its middle in u): the midpoint rule of the integral of dF_c/du.
double largestCdfError(const DiskKernel& kernel, const std::function<double(int, double)>& cdf) {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c) {
        double below = 0.0;
        for (int k = 0; k < kernel.count; ++k) {
            const DiskSample& s = kernel.samples[size_t(k)];
            largest = std::fmax(largest, std::fabs(below + 0.5 * s.weight[c] - cdf(c, s.radiusMm)));
            below += s.weight[c];
        }
    }
    return largest;
}

// The bound on that error, per sample count: the midpoint rule's error on a stratum of width
// 1/N is (1/N)^3 max|g''| / 24 with g = dF_c/du <= 3, summed over N strata O(1/N^2); measured
// (skin, soft Burley): 8 samples 2.1e-2 / 1.5e-2, 40: 8.7e-4 / 5.1e-4, 128: 7.6e-5 / 5.1e-5,
// i.e. at most 1.35 / N^2. The bound 2.5 / N^2 (3.9e-2, 1.6e-3, 1.5e-4) is about twice that.
// Broken on purpose (tests/unit, 40 / 128 samples): radii x1.05 gave 2.75e-2 (skin) and 1.59e-2
// (Burley); every channel weighted by red's weights 0.54; at 8 samples the bound is too loose
// to see a 5% radius error (2.4e-2 against 3.9e-2), which the 40- and 128-sample rows catch.
double cdfBound(int samples) { return 2.5 / (double(samples) * samples); }

}  // namespace

TEST(DiskKernel, BurleyProfileKeepsItsParameters) {
    Result<DiffusionProfile> fit = fitBurleyGaussians(kSoft);
    ASSERT_TRUE(fit.ok());
    ASSERT_TRUE(fit->burley().has_value());
    EXPECT_EQ(fit->burley()->albedo, kSoft.albedo);
    EXPECT_EQ(fit->burley()->scatteringDistanceMm, kSoft.scatteringDistanceMm);
    EXPECT_FALSE(skinProfile().burley().has_value());
}

TEST(DiskKernel, WeightsSumToOnePerChannel) {
    Result<DiffusionProfile> soft = fitBurleyGaussians(kSoft);
    ASSERT_TRUE(soft.ok());
    for (const DiffusionProfile* profile : {&skinProfile(), &marbleProfile(), static_cast<const DiffusionProfile*>(&*soft)}) {
        for (int samples : {kMinDiskSamples, 40, kMaxDiskSamples}) {
            Result<DiskKernel> kernel = makeDiskKernel(*profile, samples);
            ASSERT_TRUE(kernel.ok()) << kernel.error().message();
            ASSERT_EQ(kernel->count, samples);
            glm::dvec3 sums(0.0);
            for (int k = 0; k < samples; ++k) {
                const DiskSample& s = kernel->samples[size_t(k)];
                for (int c = 0; c < 3; ++c) EXPECT_GT(s.weight[c], 0.0f);
                if (k > 0) EXPECT_GT(s.radiusMm, kernel->samples[size_t(k - 1)].radiusMm);
                sums += glm::dvec3(s.weight);
            }
            // Float weights of doubles that sum to 1: N roundings of 6e-8 relative.
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(sums[c], 1.0, 1e-5) << profile->name() << " " << samples;
        }
    }
}

// The cumulative weight against the exact profile's CDF. For a Burley profile it is Burley's
// closed form, not the six-Gaussian fit's, whose CDF is off by 1.2-1.9% (measureBurleyFit): a kernel
// made from the fit (DiskKernel.cpp ignoring burley()) fails the bound by far (measured 1.85e-2
// at 40 and 128 samples, bounds 1.6e-3 and 1.5e-4).
TEST(DiskKernel, CumulativeWeightFollowsTheProfilesCdf) {
    Result<DiffusionProfile> soft = fitBurleyGaussians(kSoft);
    ASSERT_TRUE(soft.ok());
    for (int samples : {kMinDiskSamples, 40, kMaxDiskSamples}) {
        Result<DiskKernel> burley = makeDiskKernel(*soft, samples);
        ASSERT_TRUE(burley.ok());
        const double burleyError = largestCdfError(*burley, [](int c, double r) { return paperBurleyCdf(kSoft, c, r); });
        Result<DiskKernel> skin = makeDiskKernel(skinProfile(), samples);
        ASSERT_TRUE(skin.ok());
        const double skinError = largestCdfError(*skin, [](int c, double r) { return gaussianCdf(skinProfile(), c, r); });
        std::printf("[ measured ] %3d samples: largest CDF error skin %.2e, soft Burley %.2e (bound %.2e)\n", samples,
                    skinError, burleyError, cdfBound(samples));
        EXPECT_LT(skinError, cdfBound(samples));
        EXPECT_LT(burleyError, cdfBound(samples));
    }
}

TEST(DiskKernel, WidthScaleScalesTheRadii) {
    Result<DiskKernel> unit = makeDiskKernel(skinProfile(), 40);
    Result<DiskKernel> wide = makeDiskKernel(skinProfile(), 40, 1.5f);
    ASSERT_TRUE(unit.ok() && wide.ok());
    for (int k = 0; k < 40; ++k) {
        EXPECT_FLOAT_EQ(wide->samples[size_t(k)].radiusMm, 1.5f * unit->samples[size_t(k)].radiusMm);
        EXPECT_EQ(wide->samples[size_t(k)].weight, unit->samples[size_t(k)].weight);
    }
}

// Golden-angle spiral: theta_k = k pi (3 - sqrt 5) modulo 2 pi.
TEST(DiskKernel, AnglesFollowTheGoldenSpiral) {
    Result<DiskKernel> kernel = makeDiskKernel(skinProfile(), 40);
    ASSERT_TRUE(kernel.ok());
    for (int k = 0; k < 40; ++k) {
        const double expected = std::fmod(k * M_PI * (3.0 - std::sqrt(5.0)), 2.0 * M_PI);
        EXPECT_NEAR(kernel->samples[size_t(k)].angleRad, expected, 1e-5) << k;
    }
}

TEST(DiskKernel, SameInputSameBits) {
    Result<DiffusionProfile> soft = fitBurleyGaussians(kSoft);
    ASSERT_TRUE(soft.ok());
    Result<DiskKernel> a = makeDiskKernel(*soft, 64, 1.2f);
    Result<DiskKernel> b = makeDiskKernel(*soft, 64, 1.2f);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(std::memcmp(a->samples.data(), b->samples.data(), sizeof(DiskSample) * 64), 0);
}

TEST(DiskKernel, RejectsBadSampleCountsAndWidths) {
    EXPECT_FALSE(makeDiskKernel(skinProfile(), kMinDiskSamples - 1).ok());
    EXPECT_FALSE(makeDiskKernel(skinProfile(), kMaxDiskSamples + 1).ok());
    EXPECT_FALSE(makeDiskKernel(skinProfile(), 40, 0.0f).ok());
    EXPECT_FALSE(makeDiskKernel(skinProfile(), 40, NAN).ok());
}
