// Separable Gaussian blur kernels (Chappuis 2011 §2.2.4).
#include "sss/BlurKernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace dermis;

namespace {

// Variance of a sampled signal on a grid of spacing dx, about its mean.
double gridVariance(const std::vector<double>& signal, double dx) {
    double mass = 0.0, mean = 0.0, second = 0.0;
    for (size_t k = 0; k < signal.size(); ++k) {
        const double y = double(k) * dx;
        mass += signal[k];
        mean += signal[k] * y;
        second += signal[k] * y * y;
    }
    mean /= mass;
    return second / mass - mean * mean;
}

// Blurs a Gaussian of standard deviation s with the kernel scaled to standard deviation t, on a
// grid fine enough that every tap lands on a sample (offset x_i t = (i - half) * 4 samples).
double convolvedVariance(const BlurKernel& kernel, double s, double t) {
    const int taps = int(kernel.weights.size());
    const int half = taps / 2;
    const double dx = (double(kernel.offsetsSigma[size_t(half + 1)]) * t) / 4.0;
    const int samples = int(std::ceil(24.0 * (s + t) / dx)) | 1;
    const double centre = 0.5 * (samples - 1) * dx;
    std::vector<double> input(static_cast<size_t>(samples)), output(static_cast<size_t>(samples), 0.0);
    for (int k = 0; k < samples; ++k) {
        const double y = k * dx - centre;
        input[size_t(k)] = std::exp(-y * y / (2.0 * s * s));
    }
    for (int k = 0; k < samples; ++k)
        for (int i = 0; i < taps; ++i) {
            const int source = k - 4 * (i - half);
            if (source >= 0 && source < samples) output[size_t(k)] += double(kernel.weights[size_t(i)]) * input[size_t(source)];
        }
    return gridVariance(output, dx);
}

}  // namespace

TEST(BlurKernel, WeightsSumToOneForEveryOddCount) {
    for (float extent : {1.0f, 2.0f, 3.0f, 4.5f})
        for (int taps = kMinBlurTaps; taps <= kMaxBlurTaps; taps += 2) {
            Result<BlurKernel> kernel = makeGaussianKernel(taps, extent);
            ASSERT_TRUE(kernel.ok()) << kernel.error().message();
            ASSERT_EQ(kernel->weights.size(), size_t(taps));
            ASSERT_EQ(kernel->offsetsSigma.size(), size_t(taps));
            double sum = 0.0;
            for (float w : kernel->weights) {
                EXPECT_GT(w, 0.0f);
                sum += w;
            }
            EXPECT_NEAR(sum, 1.0, 1e-6) << taps << " taps, extent " << extent;
        }
}

TEST(BlurKernel, IsSymmetricAndEvenlySpacedOverTheExtent) {
    for (int taps = kMinBlurTaps; taps <= kMaxBlurTaps; taps += 2) {
        const BlurKernel kernel = makeGaussianKernel(taps, 3.0f).value();
        const size_t n = size_t(taps);
        EXPECT_FLOAT_EQ(kernel.offsetsSigma.front(), -3.0f);
        EXPECT_FLOAT_EQ(kernel.offsetsSigma.back(), 3.0f);
        EXPECT_EQ(kernel.offsetsSigma[n / 2], 0.0f);
        const float spacing = 6.0f / float(taps - 1);
        for (size_t i = 0; i < n; ++i) {
            EXPECT_EQ(kernel.weights[i], kernel.weights[n - 1 - i]);
            EXPECT_EQ(kernel.offsetsSigma[i], -kernel.offsetsSigma[n - 1 - i]);
            if (i > 0) { EXPECT_NEAR(kernel.offsetsSigma[i] - kernel.offsetsSigma[i - 1], spacing, 1e-5f); }
            // Rising towards the centre, except that the outermost tap, which stands for the
            // whole tail, can outweigh its neighbour when the taps are dense.
            if (i > 1 && i <= n / 2) { EXPECT_GT(kernel.weights[i], kernel.weights[i - 1]); }
        }
    }
}

TEST(BlurKernel, SevenTapsOverThreeSigmaAreChappuisWeights) {
    // Chappuis 2011 §2.2.4: {0.006, 0.061, 0.242, 0.383, 0.242, 0.061, 0.006} at offsets -3..3.
    const BlurKernel kernel = makeGaussianKernel(7, 3.0f).value();
    const float expected[7] = {0.006f, 0.061f, 0.242f, 0.383f, 0.242f, 0.061f, 0.006f};
    for (size_t i = 0; i < 7; ++i) {
        EXPECT_NEAR(kernel.weights[i], expected[i], 1e-3f) << i;
        EXPECT_FLOAT_EQ(kernel.offsetsSigma[i], float(i) - 3.0f);
    }
}

TEST(BlurKernel, RejectsBadTapCountsAndExtentsNamingTheCount) {
    for (int taps : {-1, 0, 1, 2, 4, 8, 32, 35, 1000}) {
        Result<BlurKernel> kernel = makeGaussianKernel(taps);
        ASSERT_FALSE(kernel.ok()) << taps;
        EXPECT_EQ(kernel.error().what, "a blur kernel needs an odd tap count in [3, 33], got " + std::to_string(taps));
    }
    for (float extent : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        Result<BlurKernel> kernel = makeGaussianKernel(9, extent);
        ASSERT_FALSE(kernel.ok()) << extent;
        EXPECT_NE(kernel.error().what.find("9-tap blur kernel's extent must be finite and > 0"), std::string::npos) << kernel.error().what;
    }
}

TEST(BlurKernel, ConvolvingAGaussianAddsTheVariances) {
    constexpr double kS = 1.3, kT = 1.0;
    for (int taps = kMinBlurTaps; taps <= kMaxBlurTaps; taps += 2) {
        const BlurKernel kernel = makeGaussianKernel(taps, 3.0f).value();
        const double variance = convolvedVariance(kernel, kS, kT);
        // Exactly s^2 + (the kernel's own variance) t^2, whatever the tap count...
        EXPECT_NEAR(variance / (kS * kS + double(kernelVarianceSigma2(kernel)) * kT * kT), 1.0, 1e-4) << taps << " taps";
        // ...which is s^2 + t^2 within a few % from 7 taps up (Sheppard's h^2/12 excess).
        if (taps >= 7) { EXPECT_NEAR(variance / (kS * kS + kT * kT), 1.0, 0.03) << taps << " taps"; }
    }
    // Chappuis 2011's 7 taps over +-3 sigma: 1 + 1/12 less what the tail cells give back.
    EXPECT_NEAR(kernelVarianceSigma2(makeGaussianKernel(7, 3.0f).value()), 1.08, 0.005);
    EXPECT_NEAR(kernelVarianceSigma2(makeGaussianKernel(33, 3.0f).value()), 1.0, 0.01);
}
