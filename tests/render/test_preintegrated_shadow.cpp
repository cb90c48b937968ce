// Pre-integrated shadows (sss/PreintegratedShadow.h) in a frame: a straight shadow edge on a flat
// skin floor, cast by a square blocker, rendered with sss.technique = preintegrated. On a flat
// surface the technique's falloff is N.L, so what it scatters across the edge is the shadow alone,
// and the exact answer is the light's own penumbra convolved with the profile's 1-D marginal:
//   delta sun:   sum_i w_i Phi(x / sigma_i);
//   5-degree sun: sum_i w_i integral N(x - t; sigma_i) V(t) dt, V the disc-segment closed form
//                 (support/PenumbraEdge.h), integrated here on a fine grid.
// x is the floor's distance from the geometric edge, known from the scene's geometry.
#include "PenumbraEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "sss/DiffusionProfile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// The sun travels along (1, -1, 0), so the shadow's geometric edge lies at x = 0 on the floor.

std::string sceneJson(double sunDiameterDeg, const std::string& technique) {
    return R"({
      "camera": {"position_m": [0, 0.15, 0], "target_m": [0, 0, 0], "up": [0, 0, -1],
                 "vertical_fov_deg": 30, "near_m": 0.01, "far_m": 2},
      "lights": [{"type": "directional", "direction": [1, -1, 0], "intensity": 1, "angular_diameter_deg": )" +
           std::to_string(sunDiameterDeg) + R"(}],
      "characters": [
        {"name": "floor", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.3},
         "material": {"albedo": [1, 1, 1], "rho_s": 0, "profile": "skin"}},
        {"name": "blocker", "mesh": {"procedural": "plane"}, "transform": {"translation_m": [-0.15, 0.05, 0], "scale": 0.2},
         "material": {"albedo": [1, 1, 1], "profile": "none"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "energy_conservation": false, "ssao": {"enabled": false},
                   "transmittance": {"enabled": false}, "shadow": {"map_size": 2048},
                   "sss": {"technique": ")" +
           technique + R"("}}
    })";
}

double floorX(int column, int width = kEdgeWidth, int height = kEdgeHeight) {
    const double metresPerPixel = 2.0 * kEdgeCameraHeightM * std::tan(0.5 * kEdgeFovDeg * kPi / 180.0) / height;
    return (column + 0.5 - 0.5 * width) * metresPerPixel;
}

// The sun's own visibility at floor x (m): the disc-segment closed form (test_shadows.cpp says why).
double sunVisibility(double sunDiameterDeg, double x) {
    if (sunDiameterDeg <= 0.0) return x > 0.0 ? 1.0 : 0.0;
    const double thetaEdge = std::atan2(kEdgeBlockerHeightM, kEdgeBlockerXM - x);
    return discSegmentVisibility(std::sin(thetaEdge - 0.75 * kPi) / std::sin(0.5 * sunDiameterDeg * kPi / 180.0));
}

// The profile's marginal convolved with the sun's penumbra at x (m), per channel.
glm::dvec3 scatteredEdge(double sunDiameterDeg, double x) {
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : skinProfile().gaussians()) {
        const double sigmaM = std::sqrt(double(g.varianceMm2)) * 1e-3;
        double value;
        if (sunDiameterDeg <= 0.0) {
            value = 0.5 * std::erfc(-x / (sigmaM * std::sqrt(2.0)));
        } else {
            const int n = 4000;
            const double lo = x - 8.0 * sigmaM, dt = 16.0 * sigmaM / n;
            value = 0.0;
            for (int k = 0; k <= n; ++k) {
                const double t = lo + k * dt, u = (x - t) / sigmaM;
                value += (k == 0 || k == n ? 0.5 : 1.0) * dt * std::exp(-0.5 * u * u) / (sigmaM * std::sqrt(2.0 * kPi)) *
                         sunVisibility(sunDiameterDeg, t);
            }
        }
        sum += glm::dvec3(g.weight) * value;
    }
    return sum;
}

struct EdgeError {
    double worstRed = 0.0;       // largest |rendered - expected| in red within 8 mm of the edge
    glm::dvec3 darkSide{0.0};    // mean rendered over x in [-3, -0.5] mm: the light scattered into the shadow
    glm::dvec3 darkExpected{0.0};
    glm::dvec3 litSide{0.0};     // mean rendered over x in [0.5, 3] mm: the light scattered out of the lit side
    glm::dvec3 litExpected{0.0};
};

class PreintegratedShadows : public RenderFixture {
protected:
    EdgeError measure(double sunDiameterDeg, const std::string& technique) {
        TempDir dir;
        writeTextFile(dir.file("edge.json"), sceneJson(sunDiameterDeg, technique));
        load(dir.file("edge.json"));
        const Image image = render(Aov::Irradiance, kEdgeWidth, kEdgeHeight);
        EdgeError e;
        if (image.empty()) {
            ADD_FAILURE() << "no image";
            return e;
        }
        EXPECT_EQ(countNonFinite(image), 0u);
        std::vector<glm::dvec3> row(kEdgeWidth, glm::dvec3(0.0));
        const int rows = 20;
        for (int y = kEdgeHeight / 2 - rows / 2; y < kEdgeHeight / 2 + rows / 2; ++y) {
            for (int x = 0; x < kEdgeWidth; ++x) row[size_t(x)] += glm::dvec3(image.at(x, y)) / double(rows);
        }
        // The lit level: the right tenth of the frame, over 5 cm from the edge.
        glm::dvec3 lit(0.0);
        for (int x = kEdgeWidth * 9 / 10; x < kEdgeWidth; ++x) lit += row[size_t(x)] / double(kEdgeWidth - kEdgeWidth * 9 / 10);
        int dark = 0, litCount = 0;
        for (int x = 0; x < kEdgeWidth; ++x) {
            const double xM = floorX(x);
            if (std::fabs(xM) > 0.008) continue;
            const glm::dvec3 rendered = row[size_t(x)] / lit;
            const glm::dvec3 expected = scatteredEdge(sunDiameterDeg, xM);
            e.worstRed = std::max(e.worstRed, std::fabs(rendered.r - expected.r));
            if (xM >= -0.003 && xM <= -0.0005) {
                e.darkSide += rendered;
                e.darkExpected += expected;
                ++dark;
            }
            if (xM >= 0.0005 && xM <= 0.003) {
                e.litSide += rendered;
                e.litExpected += expected;
                ++litCount;
            }
        }
        if (dark > 0 && litCount > 0) {
            e.darkSide /= double(dark);
            e.darkExpected /= double(dark);
            e.litSide /= double(litCount);
            e.litExpected /= double(litCount);
        }
        std::printf("[ measured ] %s, %.0f-degree sun: worst red %.4f; dark side rgb %.4f %.4f %.4f (exact %.4f %.4f %.4f); "
                    "lit side %.4f %.4f %.4f (exact %.4f %.4f %.4f)\n",
                    technique.c_str(), sunDiameterDeg, e.worstRed, e.darkSide.r, e.darkSide.g, e.darkSide.b, e.darkExpected.r,
                    e.darkExpected.g, e.darkExpected.b, e.litSide.r, e.litSide.g, e.litSide.b, e.litExpected.r, e.litExpected.g,
                    e.litExpected.b);
        return e;
    }
};

}  // namespace

// Bounds. The light scattered into the shadow and out of the lit side, each side's mean over 0.5-3 mm
// from the edge: within 10% of the exact mean per channel, plus 5e-3 (green and blue scatter
// little: blue keeps 4e-4 of the light past the edge). Red, the channel that scatters, within 0.06
// of the exact edge at every pixel within 8 mm. What the frame adds to the table's own error (1e-6,
// unit tests): the 64 taps quantise the coverage in steps of 1/64 (a staircase in x of 0.07 mm
// steps near the edge), the shadow map's texels (0.2 mm) and bias shift the edge by up to 0.2 mm,
// which near the edge is 0.04 in red, and PCSS estimates the sun's penumbra from a mean blocker
// depth (2.8-3.3% wide, test_shadows.cpp); the disc cuts the light scattered past 2 sigma (2% of red).
// Measured: worst red 0.039 (delta sun) and 0.038 (5-degree sun); dark-side red 0.066 against
// 0.075 and 0.267 against 0.259; lit-side red 0.934 against 0.925 and 0.726 against 0.732.
// Broken on purpose, each fails: the shadow not scattered (plain PCSS visibility), worst red 0.29
// and dark-side red 0 against 0.075 (delta sun); the disc across the light instead of along the
// surface (stretched by 1/cos 45 degrees on this floor), worst red 0.091 and 0.12; the penumbra not
// stretched onto the surface (no 1/cos(N, L)), 5-degree sun worst red 0.098 and dark-side red 0.201
// against 0.259.
TEST_F(PreintegratedShadows, HardAndSoftEdgesScatterAsTheProfileDoes) {
    for (double sun : {0.0, 5.0}) {
        const EdgeError e = measure(sun, "preintegrated");
        EXPECT_LT(e.worstRed, 0.06) << sun;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(e.darkSide[c], e.darkExpected[c], 0.1 * e.darkExpected[c] + 5e-3) << sun << " dark side, channel " << c;
            EXPECT_NEAR(e.litSide[c], e.litExpected[c], 0.1 * (1.0 - e.litExpected[c]) + 5e-3) << sun << " lit side, channel " << c;
        }
    }
}

// Where skin's sigma (1.41 mm) covers under DERMIS_PREINTEGRATED_SHADOW_MIN_SIGMA_PX = 0.5 pixels,
// the lighting pass takes the plain shadow lookup: at 40 x 22 pixels (3.7 mm each; sigma 0.39 px)
// the first column left of the edge (its centre 1.8 mm into the shadow) is black, as PCSS gives a
// delta sun's shadow, while at 64 x 36 (2.3 mm pixels, sigma 0.63 px) the first column left of
// the edge (1.1 mm into the shadow) keeps the light red scatters there (sum_i w_i Phi(-x / sigma_i)).
// Measured: 0 and 0.110 of the lit level. Broken on purpose: the threshold at 0 pixels (always
// scattered) gives 0.058 at 40 x 22 and fails.
TEST_F(PreintegratedShadows, DistantSkinTakesThePlainShadow) {
    TempDir dir;
    writeTextFile(dir.file("edge.json"), sceneJson(0.0, "preintegrated"));
    load(dir.file("edge.json"));
    for (const auto& [width, height, scatters] : {std::tuple{40, 22, false}, std::tuple{64, 36, true}}) {
        const Image image = render(Aov::Irradiance, width, height);
        ASSERT_FALSE(image.empty());
        int darkColumn = -1;
        for (int x = 0; x < width; ++x) {
            if (floorX(x, width, height) < 0.0) darkColumn = x;
        }
        ASSERT_GE(darkColumn, 0);
        const double red = image.at(darkColumn, height / 2).r / image.at(width - 1, height / 2).r;
        std::printf("[ measured ] %dx%d: red %.1f mm into the shadow %.4f of the lit level\n", width, height,
                    -floorX(darkColumn, width, height) * 1e3, red);
        if (scatters) {
            EXPECT_GT(red, 0.03);
        } else {
            EXPECT_LT(red, 1e-3);
        }
    }
}
