// Image comparison figures and the false-colour difference image.
#include "core/ImageMetrics.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;

using test::solidImage;

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
    const Image a = solidImage(8, 4, 0.5f);
    auto d = compareImages(a, a);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->pixels, 32u);
    EXPECT_EQ(d->rmse, 0.0);
    EXPECT_EQ(d->relativeRmse, 0.0);
    EXPECT_EQ(d->maxAbsDifference, 0.0);
    EXPECT_EQ(d->psnrDb, kMaxPsnrDb);
    EXPECT_DOUBLE_EQ(d->peak, 0.5);
}

TEST(ImageMetrics, KnownDifferenceGivesTheClosedForms) {
    const Image reference = solidImage(4, 4, 1.0f);
    Image test = reference;
    for (size_t i = 0; i < 8; ++i) test.texels[i] = glm::vec4(1.1f, 1.1f, 1.1f, 1.0f);  // half the pixels off by 0.1
    auto d = compareImages(reference, test);
    ASSERT_TRUE(d.ok());
    EXPECT_NEAR(d->rmse, std::sqrt(0.01 / 2.0), 1e-6);
    EXPECT_NEAR(d->relativeRmse, std::sqrt(0.01 / 2.0), 1e-6);
    EXPECT_NEAR(d->maxAbsDifference, 0.1, 1e-6);
    EXPECT_NEAR(d->psnrDb, 10.0 * std::log10(1.0 / 0.005), 1e-4);
}

TEST(ImageMetrics, MaskSelectsThePixels) {
    const Image reference = solidImage(4, 1, 1.0f);
    Image test = reference;
    test.texels[3] = glm::vec4(5.0f);
    std::vector<uint8_t> mask = {1, 1, 1, 0};
    auto d = compareImages(reference, test, mask);
    ASSERT_TRUE(d.ok());
    EXPECT_EQ(d->pixels, 3u);
    EXPECT_EQ(d->maxAbsDifference, 0.0);
}

// The object AOV holds k for character k - 1 as a half float, read back a
// rounding off (aov.frag): ids are rounded, and the background is 0.
TEST(ImageMetrics, ObjectMaskSelectsOneIdRounded) {
    Image ids = solidImage(4, 1, 0.0f);
    ids.texels[1].r = 0.9995f;
    ids.texels[2].r = 2.0004f;
    ids.texels[3].r = 1.0f;
    EXPECT_EQ(objectMask(ids, 0), (std::vector<uint8_t>{1, 0, 0, 0}));
    EXPECT_EQ(objectMask(ids, 1), (std::vector<uint8_t>{0, 1, 0, 1}));
    EXPECT_EQ(objectMask(ids, 2), (std::vector<uint8_t>{0, 0, 1, 0}));
}

TEST(ImageMetrics, BadInputsAreErrors) {
    EXPECT_FALSE(compareImages(solidImage(4, 4, 1.0f), solidImage(4, 3, 1.0f)).ok());
    EXPECT_FALSE(compareImages(solidImage(4, 4, 1.0f), solidImage(4, 4, 1.0f), std::vector<uint8_t>(3, 1)).ok());
    EXPECT_FALSE(compareImages(solidImage(4, 4, 1.0f), solidImage(4, 4, 1.0f), std::vector<uint8_t>(16, 0)).ok());
}

TEST(ImageMetrics, NonFiniteTexelsAreInfinitelyWrong) {
    const Image reference = solidImage(2, 2, 1.0f);
    Image test = reference;
    test.texels[1].g = NAN;
    auto d = compareImages(reference, test);
    ASSERT_TRUE(d.ok());
    EXPECT_TRUE(std::isinf(d->maxAbsDifference));
    EXPECT_TRUE(std::isinf(d->rmse));
    EXPECT_EQ(d->psnrDb, 0.0);
}

TEST(ImageMetrics, PercentileOfDifferences) {
    const Image reference = solidImage(10, 10, 0.0f);
    Image test = reference;
    for (size_t i = 0; i < test.texels.size(); ++i) test.texels[i].g = float(i) / 100.0f;
    EXPECT_NEAR(differencePercentile(reference, test, {}, 0.5), 0.49, 1e-6);
    EXPECT_NEAR(differencePercentile(reference, test, {}, 1.0), 0.99, 1e-6);
    EXPECT_EQ(differencePercentile(reference, solidImage(2, 2, 0.0f), {}, 0.5), 0.0);
}

TEST(ImageMetrics, NiceNumbersRoundUp) {
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(0.03), 0.05);
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(0.05), 0.05);
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(0.051), 0.1);
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(7.0), 10.0);
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(1.0), 1.0);
    EXPECT_DOUBLE_EQ(roundUpToNiceNumber(0.0), 1.0);
}

TEST(ImageMetrics, HeatmapHasAScaleBarAndGreyOutsideTheMask) {
    const Image reference = solidImage(100, 50, 1.0f);
    Image test = reference;
    test.at(10, 10) = glm::vec4(1.3f, 1.0f, 1.0f, 1.0f);
    std::vector<uint8_t> mask(reference.texels.size(), 1);
    mask[0] = 0;
    const Image heatmap = differenceHeatmap(reference, test, mask);
    EXPECT_EQ(heatmap.height, 60);  // at least tall enough for the labels
    EXPECT_GT(heatmap.width, reference.width + 50);
    for (const glm::vec4& t : heatmap.texels) {
        for (int c = 0; c < 4; ++c) ASSERT_TRUE(t[c] >= 0.0f && t[c] <= 1.0f);
    }
    EXPECT_FLOAT_EQ(heatmap.at(0, 0).r, 0.12f);            // outside the mask
    EXPECT_EQ(glm::vec3(heatmap.at(1, 0)), glm::vec3(0.0f));  // no difference: the ramp's start
    // 0.3 on a scale of 0.5: 60% up the ramp, brighter than the zero end.
    EXPECT_GT(heatmap.at(10, 10).r, 0.5f);
    // The bar's top is the ramp's end.
    EXPECT_GT(heatmap.at(reference.width + 12, 4).g, 0.9f);
}
