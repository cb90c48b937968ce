// The reference's fast path (Embree rays, each sample's value computed once:
// SampleMemo.h) against the slow path it replaced (the in-house BVH, every
// value computed where it is needed), on the default head, without and with an
// environment (the built-in sky, whose sun casts hard shadows). Both draw the
// same environment rays per point, so they differ only where the two ray
// tracers disagree on a ray that grazes an edge: far below the image's own
// noise, which the progressive mode estimates. And the memo alone changes
// nothing: with the same ray tracer the images are bit-identical.
#include "TestSupport.h"

#include "core/ImageMetrics.h"
#include "reference/ReferenceRenderer.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace dermis;

namespace {

constexpr int kWidth = 32;
constexpr int kHeight = 18;

Scene headScene(bool environment) {
    auto scene = loadScene(test::contentScene("default.json"));
    EXPECT_TRUE(scene.ok());
    if (environment) {
        scene->lights.clear();
        scene->environment.source = "sky";
    }
    return *scene;
}

Image render(const Scene& scene, bool embree, bool memo, reference::ReferenceStats* stats = nullptr) {
    reference::ReferenceOptions options;
    options.quadrature.density = 2.0f;  // the paths are compared with each other, not with the truth
    options.samplesPerPixel = 1;
    options.embree = embree;
    options.sampleMemo = memo;
    auto renderer = reference::ReferenceRenderer::load(scene, options);
    EXPECT_TRUE(renderer.ok());
    Image image = renderer->renderDiffuse(kWidth, kHeight);
    if (stats) *stats = renderer->stats();
    return image;
}

// 1 where both images cover the pixel fully.
std::vector<uint8_t> coveredByBoth(const Image& a, const Image& b) {
    std::vector<uint8_t> mask(a.texels.size());
    for (size_t p = 0; p < mask.size(); ++p) mask[p] = a.texels[p].a == 1.0f && b.texels[p].a == 1.0f;
    return mask;
}

}  // namespace

// ctest: slow
TEST(ReferenceFastPath, MemoChangesNothing) {
    const Scene scene = headScene(true);
    reference::ReferenceStats stats;
    const Image memo = render(scene, true, true, &stats);
    const Image plain = render(scene, true, false);
    ASSERT_EQ(memo.texels.size(), plain.texels.size());
    for (size_t p = 0; p < memo.texels.size(); ++p) ASSERT_EQ(memo.texels[p], plain.texels[p]) << "pixel " << p;
    // The memo was used: neighbouring x_o share the cells of the wider Gaussians (6.7 % of
    // the values here, with x_o 9 mm apart; more at real sizes).
    EXPECT_GT(stats.sampleMemoHits, stats.sampleLookups / 50);
}

// ctest: slow
TEST(ReferenceFastPath, EqualsTheSlowPathWithinItsNoise) {
    for (const bool environment : {false, true}) {
        const Scene scene = headScene(environment);
        const Image fast = render(scene, true, true);
        const Image slow = render(scene, false, false);
        const std::vector<uint8_t> mask = coveredByBoth(fast, slow);
        auto difference = compareImages(slow, fast, mask);
        ASSERT_TRUE(difference.ok());
        EXPECT_GT(difference->pixels, 80u);  // the face fills part of the view
        std::printf("%s: %zu pixels, relative RMSE %.2e between the paths, largest difference %.2e\n",
                    environment ? "sky" : "lights", difference->pixels, difference->relativeRmse,
                    difference->maxAbsDifference);
        // Measured: 3.9e-6 with the lights, 1.9e-5 under the sky: float rounding and a few
        // grazing rays. 2e-4 is ten times that and a tenth of the progressive mode's default
        // target. Embree's any-hit rays made to start 1 mm further out (tried on purpose) give
        // 1.9e-4 with the lights and 1.0e-3 under the sky: the sky case fails.
        EXPECT_LT(difference->relativeRmse, 2e-4);
    }
}
