// bench/ErrorCauses.h: the regions the bench splits its error into, and the
// per-region figures, checked against counts and values worked out by hand.
#include "bench/ErrorCauses.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace dermis::bench {
namespace {

constexpr int kSize = 12;

Image constantImage(float value) {
    Image image;
    image.width = kSize;
    image.height = kSize;
    image.texels.assign(size_t(kSize) * kSize, glm::vec4(value, value, value, 1.0f));
    return image;
}

// An SSS square (id 1) over pixels [2, 9] x [2, 9] on the background; the
// square's left half is 2 mm thick, its right half 6 mm, and column 9 leaves
// the part (infinite).
struct SquareScene {
    std::vector<int> ids = std::vector<int>(size_t(kSize) * kSize, 0);
    std::vector<bool> isSss = {false, true};
    Image thickness = constantImage(0.0f);

    SquareScene() {
        for (int y = 2; y <= 9; ++y) {
            for (int x = 2; x <= 9; ++x) {
                ids[size_t(y) * kSize + size_t(x)] = 1;
                const float mm = x <= 5 ? 2.0f : (x < 9 ? 6.0f : std::numeric_limits<float>::infinity());
                thickness.at(x, y) = glm::vec4(mm, 0.0f, 0.0f, 1.0f);
            }
        }
    }
};

size_t count(const std::vector<uint8_t>& regions, ErrorRegion region) {
    const std::vector<uint8_t> mask = regionMask(regions, region);
    size_t n = 0;
    for (uint8_t m : mask) n += m;
    return n;
}

TEST(ErrorCauses, RegionsPartitionTheSssPixels) {
    const SquareScene scene;
    const std::vector<uint8_t> regions = classifyRegions(kSize, kSize, scene.ids, scene.isSss, scene.thickness);
    // Off the band, a pixel's 5x5 neighbourhood lies inside the square: x and y
    // in [4, 7], 16 pixels; the band holds the other 64 - 16 = 48. With a band
    // of 1 px the interior would be 36 pixels, with 3 px 4: both fail.
    EXPECT_EQ(count(regions, ErrorRegion::All), 64u);
    EXPECT_EQ(count(regions, ErrorRegion::Silhouette), 48u);
    // Interior columns 4 and 5 are 2 mm thick (thin), 6 and 7 are 6 mm.
    EXPECT_EQ(count(regions, ErrorRegion::ThinUnder4Mm), 8u);
    EXPECT_EQ(count(regions, ErrorRegion::Thin4To8Mm), 8u);
    EXPECT_EQ(count(regions, ErrorRegion::Rest), 0u);
    // The background and opaque characters are in no region.
    EXPECT_EQ(regions[0], kNoRegion);
}

TEST(ErrorCauses, TheFrameBorderIsNoSilhouette) {
    // A character covering the whole frame has no silhouette.
    const std::vector<int> ids(size_t(kSize) * kSize, 1);
    const std::vector<uint8_t> regions = classifyRegions(kSize, kSize, ids, {false, true}, constantImage(20.0f));
    EXPECT_EQ(count(regions, ErrorRegion::Silhouette), 0u);
    EXPECT_EQ(count(regions, ErrorRegion::Rest), size_t(kSize) * kSize);
}

TEST(ErrorCauses, AnotherCharacterMakesAnEdge) {
    // Two SSS characters side by side: the band runs along their shared edge too.
    std::vector<int> ids(size_t(kSize) * kSize, 1);
    for (int y = 0; y < kSize; ++y) {
        for (int x = 6; x < kSize; ++x) ids[size_t(y) * kSize + size_t(x)] = 2;
    }
    const std::vector<uint8_t> regions = classifyRegions(kSize, kSize, ids, {false, true, true}, constantImage(20.0f));
    // Columns 4..7 are within 2 px of the other character: 4 x 12 pixels.
    EXPECT_EQ(count(regions, ErrorRegion::Silhouette), 48u);
}

TEST(ErrorCauses, EachRegionIsMeasuredOnItsOwnPixels) {
    const SquareScene scene;
    const std::vector<uint8_t> regions = classifyRegions(kSize, kSize, scene.ids, scene.isSss, scene.thickness);
    const Image reference = constantImage(1.0f);
    // The test is 10% high on the thin pixels and exact elsewhere.
    Image test = reference;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i] == uint8_t(ErrorRegion::ThinUnder4Mm)) test.texels[i] = glm::vec4(1.1f, 1.1f, 1.1f, 1.0f);
    }
    CauseErrors errors;
    measureCause(errors, ErrorCause::Scatter, reference, test, regions);
    EXPECT_NEAR(errors.relativeRmse(ErrorCause::Scatter, ErrorRegion::ThinUnder4Mm), 0.1, 1e-6);
    EXPECT_EQ(errors.relativeRmse(ErrorCause::Scatter, ErrorRegion::Silhouette), 0.0);
    // Over all 64 pixels: sqrt(8/64) x 0.1.
    EXPECT_NEAR(errors.relativeRmse(ErrorCause::Scatter), 0.1 * std::sqrt(8.0 / 64.0), 1e-6);
    // An empty region and an unmeasured cause read as NaN, not as 0.
    EXPECT_TRUE(std::isnan(errors.relativeRmse(ErrorCause::Scatter, ErrorRegion::Rest)));
    EXPECT_TRUE(std::isnan(errors.relativeRmse(ErrorCause::Total)));
}

TEST(ErrorCauses, TheMatchedReferenceAddsTheChange) {
    Image off = constantImage(0.5f);
    off.texels[3].a = 0.25f;  // coverage comes from the SSS-off render
    const Image change = constantImage(-0.125f);
    const Image matched = addImages(off, change);
    EXPECT_EQ(matched.texels[0], glm::vec4(0.375f, 0.375f, 0.375f, 1.0f));
    EXPECT_EQ(matched.texels[3].a, 0.25f);
}

}  // namespace
}  // namespace dermis::bench

namespace dermis::bench {
namespace {

// A reference pixel that is partly background (alpha < 1) is taken out of
// every region, and counted; a fully covered one stays. Two references: a
// pixel either leaves uncovered is dropped once.
TEST(ErrorCauses, PixelsTheReferenceDoesNotCoverAreLeftOutAndCounted) {
    const SquareScene square;
    std::vector<uint8_t> regions = classifyRegions(kSize, kSize, square.ids, square.isSss, square.thickness);
    Image full = constantImage(1.0f), off = constantImage(1.0f);
    full.at(2, 2).a = 0.75f;  // a silhouette pixel, a quarter background
    off.at(2, 2).a = 0.5f;
    off.at(5, 5).a = 0.0f;    // the centre ray met the background
    full.at(0, 0).a = 0.0f;   // background in both: never a region
    EXPECT_EQ(dropUncovered(regions, {&full, &off}), 2u);
    EXPECT_EQ(regions[2 * kSize + 2], kNoRegion);
    EXPECT_EQ(regions[5 * kSize + 5], kNoRegion);
    EXPECT_EQ(count(regions, ErrorRegion::All), 64u - 2u);
    // Partly covered pixels darken the reference by their background share: left in, they would
    // dominate the silhouette's error although the engine shades them right.
    full.at(3, 3).a = 0.999f;
    EXPECT_EQ(dropUncovered(regions, {&full}), 1u);
}

}  // namespace
}  // namespace dermis::bench
