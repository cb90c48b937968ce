// LEAN map baking (engine/lean/LeanBake.h; Olano & Baker 2010): the per-texel
// moments, the clamp that keeps them finite, and the mip chain's exactness.
#include "TestSupport.h"

#include "lean/LeanBake.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dermis;

namespace {

glm::vec3 encode(const glm::vec3& n) { return glm::normalize(n) * 0.5f + 0.5f; }

Image randomNormalMap(int width, int height, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<float> slope(0.0f, 0.4f);
    Image image;
    image.width = width;
    image.height = height;
    for (int i = 0; i < width * height; ++i) {
        image.texels.push_back(glm::vec4(encode(glm::vec3(slope(random), slope(random), 1.0f)), 1.0f));
    }
    return image;
}

glm::dvec4 mean(const Image& image) {
    glm::dvec4 sum(0.0);
    for (const glm::vec4& t : image.texels) sum += glm::dvec4(t);
    return sum / double(image.texels.size());
}

}  // namespace

TEST(LeanBake, TexelMomentsAreSlopeAndItsSquares) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
    const glm::vec4 first = leanFirstMoments(n * 0.5f + 0.5f);
    EXPECT_NEAR(first.x, n.x / n.z, 1e-5);
    EXPECT_NEAR(first.y, n.y / n.z, 1e-5);
    EXPECT_NEAR(first.z, first.x * first.x, 1e-5);
    EXPECT_NEAR(first.w, first.y * first.y, 1e-5);
    EXPECT_NEAR(leanCrossMoment(n * 0.5f + 0.5f), first.x * first.y, 1e-5);
    // Unnormalised (8-bit style) encodings are normalised first.
    const glm::vec4 scaled = leanFirstMoments(0.8f * n * 0.5f + 0.5f);
    EXPECT_NEAR(scaled.x, first.x, 1e-5);
    EXPECT_EQ(leanFirstMoments(glm::vec3(0.5f, 0.5f, 1.0f)), glm::vec4(0.0f));
}

TEST(LeanBake, DegenerateNormalsStayFinite) {
    // In the surface, below it, zero, NaN: never an infinite or NaN moment.
    const glm::vec3 cases[] = {{1.0f, 0.5f, 0.5f}, {0.5f, 0.0f, 0.2f}, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.0f},
                               {NAN, 0.5f, 1.0f}, {INFINITY, 0.5f, 0.5f}};
    for (const glm::vec3& encoded : cases) {
        const glm::vec4 m = leanFirstMoments(encoded);
        for (int c = 0; c < 4; ++c) EXPECT_TRUE(std::isfinite(m[c])) << c;
        // The clamp: |B| <= sqrt(1 - z^2) / z at z = kLeanMinNormalZ.
        const float limit = std::sqrt(1.0f - kLeanMinNormalZ * kLeanMinNormalZ) / kLeanMinNormalZ;
        EXPECT_LE(std::hypot(m.x, m.y), limit * (1.0f + 1e-5f));
        EXPECT_TRUE(std::isfinite(leanCrossMoment(encoded)));
    }
    // A normal lying in the surface along +x becomes the steepest allowed slope along +x.
    EXPECT_NEAR(leanFirstMoments({1.0f, 0.5f, 0.5f}).x, std::sqrt(255.0f), 1e-3);
}

TEST(LeanBake, MipChainAveragesExactlyForPowerOfTwoSizes) {
    const Image normals = randomNormalMap(16, 8, 1u);
    auto maps = bakeLeanMaps(normals, 0.3f);
    ASSERT_TRUE(maps.ok()) << maps.error().message();
    ASSERT_EQ(maps->levels(), 5);  // 16x8, 8x4, 4x2, 2x1, 1x1
    EXPECT_EQ(maps->lean1[3].width, 2);
    EXPECT_EQ(maps->lean1[3].height, 1);
    const Image& level0 = maps->lean1[0];
    const Image& level1 = maps->lean1[1];
    for (int y = 0; y < level1.height; ++y) {
        for (int x = 0; x < level1.width; ++x) {
            const glm::vec4 expected = 0.25f * (level0.at(2 * x, 2 * y) + level0.at(2 * x + 1, 2 * y) +
                                                level0.at(2 * x, 2 * y + 1) + level0.at(2 * x + 1, 2 * y + 1));
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(level1.at(x, y)[c], expected[c], 1e-6);
        }
    }
    // The 1x1 level is the mean of level 0, so its covariance is the sample
    // covariance of the slopes: positive semi-definite.
    const glm::vec4 top1 = maps->lean1.back().texels[0];
    const glm::vec4 top2 = maps->lean2.back().texels[0];
    const glm::dvec4 mean1 = mean(level0);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(top1[c], mean1[c], 1e-5);
    const double sxx = top1.z - double(top1.x) * top1.x;
    const double syy = top1.w - double(top1.y) * top1.y;
    const double sxy = top2.x - double(top1.x) * top1.y;
    EXPECT_GT(sxx, 0.05);  // slopes were drawn with a 0.4 standard deviation
    EXPECT_GT(syy, 0.05);
    EXPECT_GE(sxx * syy - sxy * sxy, 0.0);
    // The base roughness is stored as the Beckmann slope variance m^2 / 2 on every level.
    for (const Image& level : maps->lean2) EXPECT_NEAR(level.texels[0].y, 0.5f * 0.3f * 0.3f, 1e-7);
}

TEST(LeanBake, MipChainKeepsTheMeanForOddSizes) {
    const Image normals = randomNormalMap(37, 23, 2u);
    auto maps = bakeLeanMaps(normals);
    ASSERT_TRUE(maps.ok());
    ASSERT_EQ(maps->levels(), leanMipLevelCount(37, 23));
    EXPECT_EQ(maps->levels(), 6);  // 37, 18, 9, 4, 2, 1
    const glm::dvec4 mean1 = mean(maps->lean1[0]);
    const glm::dvec4 mean2 = mean(maps->lean2[0]);
    for (int level = 1; level < maps->levels(); ++level) {
        const glm::dvec4 m1 = mean(maps->lean1[static_cast<size_t>(level)]);
        const glm::dvec4 m2 = mean(maps->lean2[static_cast<size_t>(level)]);
        for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(m1[c], mean1[c], 1e-5) << "level " << level << " channel " << c;
            EXPECT_NEAR(m2[c], mean2[c], 1e-5) << "level " << level << " channel " << c;
        }
    }
    EXPECT_EQ(maps->lean2[0].texels[0], glm::vec4(maps->lean2[0].texels[0].x, 0.0f, 0.0f, 1.0f));
}

TEST(LeanBake, RefusesEmptyMapsAndBadRoughness) {
    EXPECT_FALSE(bakeLeanMaps(Image{}).ok());
    const Image normals = randomNormalMap(4, 4, 3u);
    EXPECT_FALSE(bakeLeanMaps(normals, -0.1f).ok());
    EXPECT_FALSE(bakeLeanMaps(normals, 1.5f).ok());
    EXPECT_FALSE(bakeLeanMaps(normals, NAN).ok());
    EXPECT_NE(bakeLeanMaps(normals, 2.0f).error().what.find("[0, 1]"), std::string::npos);
}

TEST(LeanBake, FilesHoldEveryMipLevel) {
    test::TempDir dir;
    const Image normals = randomNormalMap(20, 12, 4u);
    auto maps = bakeLeanMaps(normals, 0.2f);
    ASSERT_TRUE(maps.ok());
    const Status saved = saveLeanMaps(dir.file("sub/skin"), *maps);
    ASSERT_TRUE(saved.ok()) << saved.error().message();
    for (int which = 0; which < 2; ++which) {
        const std::vector<Image>& baked = which == 0 ? maps->lean1 : maps->lean2;
        auto loaded = loadMipChain(dir.file(which == 0 ? "sub/skin_lean1.exr" : "sub/skin_lean2.exr"));
        ASSERT_TRUE(loaded.ok()) << loaded.error().message();
        ASSERT_EQ(loaded->size(), baked.size());
        for (size_t level = 0; level < baked.size(); ++level) {
            ASSERT_EQ((*loaded)[level].width, baked[level].width);
            ASSERT_EQ((*loaded)[level].height, baked[level].height);
            for (size_t i = 0; i < baked[level].texels.size(); ++i) {
                EXPECT_EQ((*loaded)[level].texels[i], baked[level].texels[i]) << "level " << level;
            }
        }
    }
    EXPECT_FALSE(loadMipChain(dir.file("missing.exr")).ok());
}

// The banded bake the GPU upload uses (bakeLeanLevels, assembled by
// bakeLeanMaps) against the chain made the plain way: level 0 texel by texel
// from leanFirstMoments / leanCrossMoment, each later level leanDownsample of
// the one before. Bit for bit: the same weights are summed in the same order.
// 150 rows span three bands; odd sizes make every footprint fractional.
TEST(LeanBake, BandedBakeEqualsTheWholeImageChainBitForBit) {
    ASSERT_LT(2 * kLeanBandRows, 150);
    const Image normals = randomNormalMap(37, 150, 5u);
    auto maps = bakeLeanMaps(normals, 0.25f);
    ASSERT_TRUE(maps.ok());
    Image level1 = normals;
    Image level2 = normals;
    for (size_t i = 0; i < normals.texels.size(); ++i) {
        const glm::vec3 n(normals.texels[i]);
        level1.texels[i] = leanFirstMoments(n);
        level2.texels[i] = glm::vec4(leanCrossMoment(n), 0.5f * 0.25f * 0.25f, 0.0f, 1.0f);
    }
    ASSERT_EQ(maps->levels(), leanMipLevelCount(37, 150));
    for (int level = 0; level < maps->levels(); ++level) {
        const Image& banded1 = maps->lean1[static_cast<size_t>(level)];
        const Image& banded2 = maps->lean2[static_cast<size_t>(level)];
        ASSERT_EQ(banded1.width, level1.width);
        ASSERT_EQ(banded1.height, level1.height);
        ASSERT_EQ(banded1.texels.size(), level1.texels.size());
        for (size_t i = 0; i < level1.texels.size(); ++i) {
            ASSERT_EQ(banded1.texels[i], level1.texels[i]) << "level " << level << " texel " << i;
            ASSERT_EQ(banded2.texels[i], level2.texels[i]) << "level " << level << " texel " << i;
        }
        level1 = leanDownsample(level1);
        level2 = leanDownsample(level2);
    }
}
