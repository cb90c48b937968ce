// The progressive mode's noise estimate against the noise it estimates: the
// sphere under the built-in studio (no other light), rendered once (pass 0) and
// as the mean of many passes. The probe estimates pass 0's relative RMSE from a
// second pass over one pixel in 8; the actual spread of pass 0 about the mean of
// n passes (pass 0 among them) is sigma^2 ((n - 1) / n) in expectation, so
// sqrt(n / (n - 1)) x their RMS difference measures pass 0's noise independently.
#include "ReferenceTestScenes.h"

#include "core/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr int kWidth = 40;
constexpr int kHeight = 30;

reference::ReferenceRenderer studioSphere() {
    Scene scene = sphereScene();
    scene.lights.clear();
    scene.environment.source = "studio";
    reference::ReferenceOptions options;
    options.quadrature.density = 1.0f;  // the noise, not the quadrature, is under test
    options.samplesPerPixel = 1;
    options.environmentSamples = 4;  // noisy on purpose: an estimate well above float rounding
    options.integralEnvironmentSamples = 2;
    auto renderer = reference::ReferenceRenderer::create(scene, sphereSceneModels(false), options);
    EXPECT_TRUE(renderer.ok());
    return std::move(*renderer);
}

}  // namespace

// ctest: slow cost=35
TEST(ReferenceProgressive, ProbedEstimateMatchesTheActualSpread) {
    reference::ReferenceRenderer renderer = studioSphere();
    const Image single = renderer.renderDiffuse(kWidth, kHeight);

    reference::ProgressiveSettings probeOnly;
    probeOnly.targetRelativeRmse = 1.0;  // any estimate passes: one pass and the probe
    const Image probed = renderer.renderDiffuseProgressive(kWidth, kHeight, probeOnly);
    ASSERT_EQ(renderer.stats().passes, 1);
    const double estimate = renderer.stats().estimatedRelativeRmse;
    for (size_t p = 0; p < single.texels.size(); ++p) ASSERT_EQ(single.texels[p], probed.texels[p]);  // pass 0 itself

    reference::ProgressiveSettings many;
    many.targetRelativeRmse = 1e-9;  // never reached: every pass runs
    many.maxPasses = 16;
    const Image mean = renderer.renderDiffuseProgressive(kWidth, kHeight, many);
    ASSERT_EQ(renderer.stats().passes, 16);
    const double meanEstimate = renderer.stats().estimatedRelativeRmse;

    std::vector<uint8_t> mask(single.texels.size());
    for (size_t p = 0; p < mask.size(); ++p) mask[p] = single.texels[p].a == 1.0f;
    auto spread = compareImages(mean, single, mask);
    ASSERT_TRUE(spread.ok());
    const double actual = spread->relativeRmse * std::sqrt(16.0 / 15.0);
    std::printf("pass 0's noise: probed %.3f %%, actual %.3f %%; 16 passes' estimate %.3f %%\n", 100.0 * estimate,
                100.0 * actual, 100.0 * meanEstimate);
    ASSERT_GT(actual, 1e-3);  // noise worth estimating
    // The probe sees ~1/8 of ~900 pixels with one difference each: its own error is about
    // sqrt(2 / 110) = 13 %, and the actual spread's about 5 %; 35 % is 2.5 of their combined
    // deviations. An estimate without the 1/2 of a two-sample variance is 41 % high.
    EXPECT_NEAR(estimate, actual, 0.35 * actual);
    // The mean of 16 passes has a quarter of pass 0's noise (within the estimates' own error).
    EXPECT_NEAR(meanEstimate, actual / 4.0, 0.35 * actual / 4.0);
}

TEST(ReferenceProgressive, WithoutEnvironmentOnePassIsExact) {
    reference::ReferenceOptions options;
    options.quadrature.density = 1.0f;
    auto renderer = reference::ReferenceRenderer::create(sphereScene(), sphereSceneModels(false), options);
    ASSERT_TRUE(renderer.ok());
    const Image single = renderer->renderDiffuse(16, 12);
    reference::ProgressiveSettings settings;
    settings.targetRelativeRmse = 1e-9;
    const Image progressive = renderer->renderDiffuseProgressive(16, 12, settings);
    EXPECT_EQ(renderer->stats().passes, 1);
    EXPECT_EQ(renderer->stats().estimatedRelativeRmse, 0.0);
    for (size_t p = 0; p < single.texels.size(); ++p) ASSERT_EQ(single.texels[p], progressive.texels[p]);
}
