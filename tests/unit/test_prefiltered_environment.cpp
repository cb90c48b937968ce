// The prefiltered environment map of the split-sum specular
// (env/PrefilteredEnvironment.h) against invariants and an independent
// quadrature of its defining integral.
#include "env/EnvironmentMap.h"
#include "env/PrefilteredEnvironment.h"
#include "env/SphericalHarmonics.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>

using namespace dermis;
using test::latLongImage;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Radiance with structure at the lobes' scales: a sky gradient and two
// von Mises-Fisher blobs of angular width 0.25 and 0.15 rad, the second
// straddling the u seam (longitude 0, +Z) below the horizon.
glm::vec3 structuredRadiance(const glm::vec3& d) {
    const glm::vec3 blobA = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    const glm::vec3 blobB = glm::normalize(glm::vec3(0.0f, -0.2f, 1.0f));
    const float a = std::exp((glm::dot(d, blobA) - 1.0f) / (0.25f * 0.25f));
    const float b = std::exp((glm::dot(d, blobB) - 1.0f) / (0.15f * 0.15f));
    return glm::vec3(1.0f + 0.5f * d.y, 0.8f, 1.2f - 0.4f * d.y) + a * glm::vec3(3.0f, 2.0f, 1.0f) +
           b * glm::vec3(1.0f, 2.0f, 3.0f);
}

// The defining integral, by quadrature in polar coordinates about r, written
// independently of the library: sum L(l) D(h) (n.l) dw / sum D(h) (n.l) dw with
// n = v = r, h = normalize(l + r), D Beckmann's distribution
// exp(-tan^2 a / m^2) / (pi m^2 cos^4 a) (Walter et al. 2007 eq. 25), over the
// hemisphere about r. Midpoint rule in the polar angle (1200 steps: 1/27 of
// the narrowest lobe tested) and the azimuth (256 steps).
glm::vec3 bruteForcePrefiltered(const glm::vec3& r, float m) {
    const glm::dvec3 n(r);
    const glm::dvec3 helper = std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 t = glm::normalize(glm::cross(helper, n));
    const glm::dvec3 b = glm::cross(n, t);
    constexpr int kPolarSteps = 1200, kAzimuthSteps = 256;
    const double dPolar = 0.5 * kPi / kPolarSteps, dAzimuth = 2.0 * kPi / kAzimuthSteps;
    glm::dvec3 weighted(0.0);
    double total = 0.0;
    for (int i = 0; i < kPolarSteps; ++i) {
        const double polar = (i + 0.5) * dPolar;
        for (int j = 0; j < kAzimuthSteps; ++j) {
            const double azimuth = (j + 0.5) * dAzimuth;
            const glm::dvec3 l = std::sin(polar) * (std::cos(azimuth) * t + std::sin(azimuth) * b) + std::cos(polar) * n;
            const glm::dvec3 h = glm::normalize(l + n);
            const double cosA = glm::dot(h, n);
            const double tanSquared = (1.0 - cosA * cosA) / (cosA * cosA);
            const double d = std::exp(-tanSquared / (double(m) * m)) / (kPi * m * m * std::pow(cosA, 4.0));
            const double weight = d * glm::dot(n, l) * std::sin(polar) * dPolar * dAzimuth;
            weighted += weight * glm::dvec3(structuredRadiance(glm::vec3(l)));
            total += weight;
        }
    }
    return glm::vec3(weighted / total);
}

glm::dvec3 totalPower(const Image& map) {
    glm::dvec3 sum(0.0);
    for (int v = 0; v < map.height; ++v)
        for (int u = 0; u < map.width; ++u)
            sum += double(latLongTexelSolidAngle(v, map.width, map.height)) * glm::dvec3(glm::vec3(map.at(u, v)));
    return sum;
}

}  // namespace

TEST(PrefilteredEnvironment, LatLongUvInvertsLatLongDirection) {
    for (int v = 0; v < 8; ++v)
        for (int u = 0; u < 16; ++u) {
            const glm::vec2 uv = latLongUv(latLongDirection(u, v, 16, 8));
            EXPECT_NEAR(uv.x, (u + 0.5f) / 16.0f, 1e-6f) << u << " " << v;
            EXPECT_NEAR(uv.y, (v + 0.5f) / 8.0f, 1e-6f) << u << " " << v;
        }
}

// The level <-> roughness mapping: a round trip to 1e-5 levels (float
// rounding of log2/exp2), strictly increasing over the chain, level 0 at m = 0,
// the last level at m = 1, clamped beyond. Broken on purpose: a mapping linear
// in m below level 1 that does not meet the logarithmic part at level 1
// (m / (2 m_1)) fails the round trip by up to 0.5 levels.
TEST(PrefilteredEnvironment, RoughnessLevelMappingRoundTripsAndIsMonotonic) {
    EXPECT_EQ(kPrefilteredLevels, 6);
    EXPECT_FLOAT_EQ(prefilteredLevelOfRoughness(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(prefilteredLevelOfRoughness(1.0f), float(kPrefilteredLevels - 1));
    EXPECT_FLOAT_EQ(prefilteredLevelOfRoughness(3.0f), float(kPrefilteredLevels - 1));
    EXPECT_FLOAT_EQ(prefilteredLevelOfRoughness(-0.5f), 0.0f);
    for (float level = 0.0f; level <= float(kPrefilteredLevels - 1); level += 0.01f)
        EXPECT_NEAR(prefilteredLevelOfRoughness(prefilteredRoughnessOfLevel(level)), level, 1e-5f) << level;
    float previous = -1.0f;
    for (float m = 0.0f; m <= 1.0f; m += 0.001f) {
        const float level = prefilteredLevelOfRoughness(m);
        EXPECT_GT(level, previous) << m;
        previous = level;
    }
}

// Each prefiltered level's lobe, whose angular standard deviation is
// sqrt(2) m about R (the small-angle limit of exp(-tan^2(theta / 2) / m^2)),
// spans a few of its own texels (pi / height wide): 3.6, wide enough for
// bilinear reads (MatchesBruteForceIntegration's bound rests on it), narrow
// enough that the level is not wasted. Broken on purpose:
// DERMIS_PREFILTERED_MAX_ROUGHNESS 2 gives 7.2 texels.
TEST(PrefilteredEnvironment, EachLevelsLobeSpansAFewOfItsTexels) {
    for (int k = 1; k < kPrefilteredLevels; ++k) {
        const double lobeWidthRad = std::sqrt(2.0) * prefilteredRoughnessOfLevel(float(k));
        const double texelRad = kPi / double(kPrefilteredBaseHeight >> k);
        EXPECT_GT(lobeWidthRad / texelRad, 3.0) << k;
        EXPECT_LT(lobeWidthRad / texelRad, 6.0) << k;
    }
}

// The weights are normalised, so a uniform map must stay uniform at every
// level up to float rounding: 1e-4 relative. Broken on purpose: leaving out
// the division by the sum of the weights fails by orders of magnitude.
TEST(PrefilteredEnvironment, UniformMapStaysUniformAtEveryLevel) {
    const glm::vec3 radiance(1.0f, 0.5f, 0.25f);
    const auto chain = PrefilteredEnvironment::build(latLongImage(64, 32, [&](const glm::vec3&) { return radiance; }), 2, "");
    ASSERT_EQ(chain.levels().size(), size_t(kPrefilteredLevels));
    for (int k = 0; k < kPrefilteredLevels; ++k) {
        const Image& level = chain.levels()[size_t(k)];
        EXPECT_EQ(level.width, (2 * kPrefilteredBaseHeight) >> k);
        EXPECT_EQ(level.height, kPrefilteredBaseHeight >> k);
        for (const glm::vec4& texel : level.texels)
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(texel[c] / radiance[c], 1.0f, 1e-4f) << "level " << k;
    }
}

// Energy: sum L dw over the sphere. A blur whose kernel depends on r.l alone
// and is normalised (sum over l of K(r, l) dw_l = 1 for every r) is then
// normalised over r too (swap the sums), so it keeps the integral exactly;
// the base's area-weighted resampling keeps it exactly too. What remains is
// discretisation: each level is point-sampled at its texel centres, whose
// midpoint-rule error is O(texel^2) times the blurred sky's curvature. The
// bound is 0.2% at the last level (16 x 8, 22.5 degree texels) scaled by
// texel^2 to the others; measured: 4.9e-4 at the last level, 1.9e-4 at the
// one before, 1.7e-5 at level 3 (red, the reddest ground). Broken on purpose:
// leaving out the solid angle from the weights moves the total by 8.3% at
// the last level.
TEST(PrefilteredEnvironment, SmoothSkyKeepsItsTotalAtEveryLevel) {
    ProceduralSky sky;
    sky.sunRadiance = glm::vec3(0.0f);
    const Image map = makeProceduralSky(sky, 128);
    const glm::dvec3 expected = totalPower(map);
    const auto chain = PrefilteredEnvironment::build(map, 2, "");
    for (int k = 0; k < kPrefilteredLevels; ++k) {
        const glm::dvec3 total = totalPower(chain.levels()[size_t(k)]);
        const double texelsPerLastTexel = double(1 << (kPrefilteredLevels - 1 - k));
        const double bound = 2e-3 / (texelsPerLastTexel * texelsPerLastTexel);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c] / expected[c], 1.0, bound) << "level " << k << " channel " << c;
    }
}

// Against the independent quadrature, for directions at a blob, near both
// poles, across the u seam (either side of it) and at the horizon. At a
// level's own roughness (m = 1/16, 1/4, 1) the chain differs by its bilinear
// reads only: interpolating a peak of standard deviation s (at least 3.6
// texels: the lobe's) misses it by up to texel^2 / (8 s^2) ~ 1% of its
// height, and the last level (16 x 8) clamps v at the poles; bound 2%,
// measured 1.7%. Between levels (m = 0.02, 0.09, 0.35, 0.7) the linear blend
// of two blurs whose variances differ 4x stands in for the blur between them:
// for a Gaussian feature that misses by up to 2.2% of the feature's height
// (w^2/(w^2+2s^2) against the mean of w^2/(w^2+s^2) and w^2/(w^2+4s^2)), plus
// the bilinear error, and between the mirror (level 0) and level 1 the blend
// is of a sharp and a blurred feature; bound 4%, measured 3.6% (m = 0.02 on
// the seam's blob) and 3.1% (m = 0.35). Broken on purpose: leaving out n.l
// from the weights fails by 14%, leaving out the solid angle by 8.7%.
// Also measures the build of a 512 x 256 map on 2 threads (printed).
TEST(PrefilteredEnvironment, MatchesBruteForceIntegration) {
    const Image map = latLongImage(2 * kPrefilteredBaseHeight, kPrefilteredBaseHeight, structuredRadiance);
    const auto start = std::chrono::steady_clock::now();
    const auto chain = PrefilteredEnvironment::build(map, 2, "");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "build of " << map.width << " x " << map.height << " on 2 threads: " << seconds << " s\n";
    const glm::vec3 directions[] = {
        glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f)),      // blob A's centre
        glm::normalize(glm::vec3(0.05f, 1.0f, 0.02f)),    // near the north pole
        glm::normalize(glm::vec3(-0.03f, -1.0f, 0.05f)),  // near the south pole
        glm::normalize(glm::vec3(0.004f, -0.2f, 1.0f)),   // just east of the seam, on blob B
        glm::normalize(glm::vec3(-0.004f, -0.2f, 1.0f)),  // just west of it
        glm::normalize(glm::vec3(-1.0f, 0.0f, -0.3f)),    // the horizon
    };
    struct Case {
        float m;
        float bound;
    };
    const Case cases[] = {{1.0f / 16.0f, 0.02f}, {0.25f, 0.02f}, {1.0f, 0.02f}, {0.02f, 0.04f},
                          {0.09f, 0.04f},        {0.35f, 0.04f}, {0.7f, 0.04f}};
    for (const glm::vec3& r : directions)
        for (const Case& test : cases) {
            const glm::vec3 expected = bruteForcePrefiltered(r, test.m);
            const glm::vec3 actual = chain.radiance(r, test.m);
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(actual[c] / expected[c], 1.0f, test.bound)
                    << "r (" << r.x << ", " << r.y << ", " << r.z << ") m " << test.m << " channel " << c;
        }
}
