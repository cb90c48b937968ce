// The precomputed Beckmann table of Chappuis 2011 §2.3.
#include "brdf/BeckmannTable.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;

TEST(BeckmannTable, IsFiniteAndNonNegativeEverywhere) {
    const std::vector<float> table = makeBeckmannTable(64);
    for (float v : table) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.0f);
    }
    // Including the traps: N.H = 0 (0 * Inf) and m = 0.
    EXPECT_EQ(beckmannPH(0.0f, 0.3f), 0.0f);
    EXPECT_TRUE(std::isfinite(beckmannPH(1.0f, 0.0f)));
    EXPECT_TRUE(std::isfinite(beckmannPH(0.5f, 0.0f)));
}

TEST(BeckmannTable, MatchesTheClosedFormAtItsSamplePoints) {
    constexpr int kSize = 32;
    const std::vector<float> table = makeBeckmannTable(kSize);
    for (int y = 1; y < kSize; ++y) {
        const double m = double(y) / (kSize - 1);
        for (int x = 0; x < kSize; ++x) {
            const double nDotH = beckmannTableNDotH(x, kSize);
            if (nDotH < 0.05) continue;
            const double alpha = std::acos(nDotH);
            const double expected = std::exp(-std::pow(std::tan(alpha), 2) / (m * m)) / (m * m * std::pow(nDotH, 4));
            EXPECT_NEAR(table[size_t(y * kSize + x)], expected, 1e-4 * std::max(1.0, expected)) << "m " << m << " N.H " << nDotH;
        }
    }
}

TEST(BeckmannTable, PeaksAtOneOverMSquaredWhenNormalAndHalfVectorAlign) {
    for (float m : {0.1f, 0.3f, 0.6f}) EXPECT_NEAR(beckmannPH(1.0f, m), 1.0f / (m * m), 1e-3f / (m * m));
}

TEST(BeckmannTable, FirstColumnIsTheExactPeakAndTheLastRowIsRoughest) {
    EXPECT_FLOAT_EQ(beckmannTableNDotH(0, 256), 1.0f);
    EXPECT_FLOAT_EQ(beckmannTableNDotH(255, 256), 0.0f);
}
