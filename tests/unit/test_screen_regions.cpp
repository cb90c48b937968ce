// Disjoint covers of pixel rectangles (plan/ScreenRegions.h), checked pixel
// by pixel against the union on a small grid.
#include "plan/ScreenRegions.h"

#include <gtest/gtest.h>

#include <random>

using namespace dermis;

namespace {

constexpr int kGrid = 64;

std::vector<int> coverCount(const std::vector<glm::ivec4>& rects) {
    std::vector<int> count(kGrid * kGrid, 0);
    for (const glm::ivec4& r : rects)
        for (int y = std::max(r.y, 0); y < std::min(r.y + r.w, kGrid); ++y)
            for (int x = std::max(r.x, 0); x < std::min(r.x + r.z, kGrid); ++x) ++count[size_t(y * kGrid + x)];
    return count;
}

TEST(ScreenRegions, SparseRectanglesAreCoveredExactlyOnce) {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> position(0, kGrid - 8), size(1, 8);
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<glm::ivec4> rects;
        for (int i = 0; i < 6; ++i) rects.emplace_back(position(random), position(random), size(random), size(random));
        const std::vector<glm::ivec4> cover = disjointCover(rects);
        const std::vector<int> unionCount = coverCount(rects), coverCounts = coverCount(cover);
        size_t unionPixels = 0;
        for (int c : unionCount) unionPixels += c > 0;
        if (cover.size() == 1 && coverCounts != unionCount) {
            // Fell back to the bounding box: then the union must fill more than the share.
            EXPECT_GT(double(unionPixels), kRegionAreaShareForOneBox * double(cover[0].z) * double(cover[0].w) - 1e-9);
            continue;
        }
        for (size_t p = 0; p < unionCount.size(); ++p) {
            // Every pixel of the union once, nothing else: a pixel drawn twice would be blended twice.
            ASSERT_EQ(coverCounts[p], unionCount[p] > 0 ? 1 : 0) << "trial " << trial << " pixel " << p;
        }
    }
}

TEST(ScreenRegions, DenseOrManyRectanglesBecomeTheirBoundingBox) {
    // Two rectangles overlapping almost entirely: their union fills the box.
    const auto dense = disjointCover({{0, 0, 10, 10}, {1, 1, 10, 10}});
    ASSERT_EQ(dense.size(), 1u);
    EXPECT_EQ(dense[0], glm::ivec4(0, 0, 11, 11));
    // A diagonal of 100 separate pixels: more than kMaxScreenRegions.
    std::vector<glm::ivec4> diagonal;
    for (int i = 0; i < 100; ++i) diagonal.emplace_back(i * 2, i * 2, 1, 1);
    const auto many = disjointCover(diagonal);
    ASSERT_EQ(many.size(), 1u);
    EXPECT_EQ(many[0], glm::ivec4(0, 0, 199, 199));
    EXPECT_TRUE(disjointCover({}).empty());
    EXPECT_TRUE(disjointCover({{3, 3, 0, 5}}).empty());
}

}  // namespace
