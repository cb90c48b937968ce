// Screen-space SSS against closed forms: the furnace, the analytic edge, the
// slab's thickness and transmittance, and the stencil mask.
#include "AnalyticEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "brdf/EnergyTable.h"
#include "include/SharedConstants.glsl"
#include "sss/DiffusionProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace dermis;

namespace {

class Sss : public test::RenderFixture {};

constexpr int kTapCounts[] = {5, 9, 17};


}  // namespace

// The furnace: a uniformly lit skin plane, E = 1 straight down, seen from
// 3 cm so that at 320x180 (11 px/mm) all six Gaussians blur (the narrowest is
// 0.9 px wide). Every blur pass must run, and the diffuse AOV must be the
// closed form E x albedo x (1 - rho_s rho_dt(N.L, m)) x (1 - rho_s rho_dt(N.V, m))
// (Chappuis 2011 §2.6), rho_dt by quadrature on the CPU (brdf/EnergyTable.h),
// N.V per pixel from the pinhole camera.
TEST_F(Sss, FurnaceRunsEveryGaussianAndMatchesTheClosedForm) {
    constexpr int kWidth = 320;
    constexpr int kHeight = 180;
    for (const char* blur : {"bilateral", "control"}) {
        for (int taps : kTapCounts) {
            load("furnace.json", {"camera.position_m=[0,0.03,0]", "sss.taps=" + std::to_string(taps),
                                  std::string("sss.blur=") + blur});
            const Image image = render(Aov::Diffuse, kWidth, kHeight);
            ASSERT_EQ(test::countNonFinite(image), 0u);
            for (int g = 0; g < 6; ++g) {
                for (const char* direction : {" h", " v"}) {
                    const std::string name = "sss skin g" + std::to_string(g) + direction;
                    const PassSummary* p = pass(name);
                    EXPECT_TRUE(p && p->executed) << name << " did not run (" << blur << ", " << taps << " taps)";
                }
            }
            const Material& material = mScene->characters[0].material;
            const Light& light = mScene->lights[0];
            const double tanHalf = std::tan(glm::radians(double(mScene->camera.verticalFovDeg)) / 2.0);
            const double aspect = double(kWidth) / kHeight;
            const double lightShare = 1.0 - material.rhoS * rhoDt(1.0f, material.roughness);
            glm::dvec3 worst(0.0);
            for (int y = 0; y < kHeight; ++y) {
                for (int x = 0; x < kWidth; ++x) {
                    const glm::dvec3 ray((2.0 * (x + 0.5) / kWidth - 1.0) * tanHalf * aspect,
                                         (1.0 - 2.0 * (y + 0.5) / kHeight) * tanHalf, -1.0);
                    const double nDotV = 1.0 / glm::length(ray);
                    const double viewShare = 1.0 - material.rhoS * rhoDt(float(nDotV), material.roughness);
                    for (int c = 0; c < 3; ++c) {
                        const double expected =
                            light.intensity * light.colour[c] * material.albedo[c] * lightShare * viewShare;
                        const double error = (image.at(x, y)[c] - expected) / expected;
                        if (std::abs(error) > std::abs(worst[c])) worst[c] = error;
                    }
                }
            }
            std::printf("furnace %-9s %2d taps: worst relative error R %+.4f%% G %+.4f%% B %+.4f%%\n", blur, taps,
                        100.0 * worst.r, 100.0 * worst.g, 100.0 * worst.b);
            // 0.1% (the goal is 0.2%; measured at most 0.065%): the albedo and irradiance targets
            // are half float (up to 0.05% each way), the blur's weights sum to 1 to float rounding
            // and the accumulation is float; the energy table's bilinear lookup is within 5e-4 of
            // rho_dt, times rho_s = 0.18. An 8-bit sRGB albedo (-0.25% / -0.65% / -0.76% at 0.8 /
            // 0.6 / 0.5) or a half-float accumulation (-0.14% / -0.19% / -0.16%) fails it.
            for (int c = 0; c < 3; ++c) EXPECT_LT(std::abs(worst[c]), 0.001) << blur << " " << taps << " taps, channel " << c;
        }
    }
}

namespace {

// The flat-skin edge (AnalyticEdge.h's scene: a black|white albedo step at
// x = 0 on a plane seen straight down, no shadow, mix = 1 so the blur's input
// is the irradiance step itself) at 320x180: 0.1 mm per pixel, so even the
// narrowest Gaussian (0.08 mm = 0.8 px) blurs and all six run, and the widest
// (2.72 mm, 3 sigma = 82 px) fits in the 160 px either side of the step.
constexpr int kFlatEdgeWidth = 320;
constexpr int kFlatEdgeHeight = 180;

using test::compareEdge;
using test::EdgeComparison;
using test::printEdge;

class SssEdge : public test::RenderFixture {
protected:
    // Renders the edge and checks that `gaussians` Gaussians blurred (both passes each).
    EdgeComparison renderEdge(const std::vector<std::string>& overrides, int gaussians = 6) {
        std::vector<std::string> all = {"sss.taps=9"};
        all.insert(all.end(), overrides.begin(), overrides.end());
        load(mScenePath, all);
        const Image irradiance = render(Aov::Irradiance, kFlatEdgeWidth, kFlatEdgeHeight);
        const Image diffuse = render(Aov::Diffuse, kFlatEdgeWidth, kFlatEdgeHeight);
        for (int g = 0; g < gaussians; ++g) {
            for (const char* direction : {" h", " v"}) {
                const std::string name = "sss skin g" + std::to_string(g) + direction;
                const PassSummary* p = pass(name);
                EXPECT_TRUE(p && p->executed) << name << " did not run: every Gaussian must blur here";
            }
        }
        return compareEdge(irradiance, diffuse);
    }
    void SetUp() override {
        test::RenderFixture::SetUp();
        mScenePath = test::writeEdgeScene(mDir);
    }
    test::TempDir mDir;
    std::string mScenePath;
};

// Bounds (the measured figures are in docs/screen-space.md):
// - max error 1% of the step: the accuracy goal (measured 0.27% at 9 taps).
//   The Gaussians' cell integrals are exact for the boxes of the unblurred
//   irradiance; later steps sample a smooth chain every s pixels, which
//   costs a fraction of a percent at 9 taps;
// - fitted width scale within 1.5% of 1 in every channel: a width error of
//   5% moves the best fit by 4-5% (the mutation tests below), and skipping
//   the variance correction of the later steps by 1.4-2.4%, while the fit
//   at the right width is within 0.3% (0.997-1.001 measured). The maximum
//   error alone would not catch a 5% width error (0.66% and 0.88%).
constexpr double kEdgeMaxError = 0.01;
constexpr double kEdgeWidthTolerance = 0.015;

bool edgeMatches(const EdgeComparison& e) {
    bool widths = true;
    for (int c = 0; c < 3; ++c) widths = widths && std::abs(e.widthScale[c] - 1.0) < kEdgeWidthTolerance;
    return e.maxError < kEdgeMaxError && widths;
}

}  // namespace

TEST_F(SssEdge, FlatSkinMatchesTheExactDiffusionOfItsIrradiance) {
    const EdgeComparison e = renderEdge({});
    printEdge("9 taps (default)", e);
    // The irradiance must be a step (the two texels beside it are the albedo map's filtering, which
    // the exact diffusion takes as they are), lit uniformly: no shadow, no penumbra in the signal.
    EXPECT_LT(e.irradianceOffStep, 1e-3);
    EXPECT_LT(e.maxError, kEdgeMaxError);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e.widthScale[c], 1.0, kEdgeWidthTolerance) << "channel " << c;
}

TEST_F(SssEdge, ComparisonFailsWhenEveryWidthIsFivePercentOff) {
    for (const char* scale : {"0.95", "1.05"}) {
        const EdgeComparison e = renderEdge({std::string("sss.width_scale=") + scale});
        printEdge((std::string("width scale ") + scale).c_str(), e);
        EXPECT_FALSE(edgeMatches(e)) << "width scale " << scale << " passed the edge comparison";
    }
}

TEST_F(SssEdge, ComparisonFailsWithTheWidestGaussianDropped) {
    const EdgeComparison e = renderEdge({"sss.gaussians=5"}, 5);
    printEdge("widest Gaussian dropped", e);
    EXPECT_FALSE(edgeMatches(e));
}

TEST_F(SssEdge, TapCountTable) {
    for (int taps : {5, 7, 13, 17}) {
        const EdgeComparison e = renderEdge({"sss.taps=" + std::to_string(taps)});
        printEdge((std::to_string(taps) + " taps").c_str(), e);
        // From 7 taps on the 1% goal holds (measured 0.03-0.28%). 5 taps sample the smooth
        // chain every ~1.5 sigma of the step and cannot: measured 2.2%, bound 5% (a breakdown,
        // e.g. the old whole-pixel rounding of point-weighted taps, shows as more).
        EXPECT_LT(e.maxError, taps == 5 ? 0.05 : kEdgeMaxError) << taps << " taps";
    }
}

namespace {

struct SlabRow {
    double worstThickness = 0.0;             // relative
    glm::dvec3 worstTransmittance{0.0};      // relative, per channel
    glm::ivec3 checked{0};                   // pixels per channel where T_c(s) >= kMeasurableT
    int selfPixels = 0;                      // thinner than DERMIS_SELF_THICKNESS_MM
    double selfWorst = 0.0;                  // their largest transmitted value (must be 0)
    double thinnestMm = 1e9, thickestMm = 0.0;
};

// A channel is compared where it transmits at least 1%: there the AOV's
// value is a hundred times the float noise of the passes.
constexpr double kMeasurableT = 0.01;

}  // namespace

// The wedge (1-20 mm thick along x over 0.2 m) seen straight from above, its
// back light shining straight up through it.
// From the skin profile's variances, T_c(s) >= 1% for s up to ~3.9 mm in red
// (w = 0.078 at 7.41 mm^2), ~0.75 mm in green (0.198 at 0.187 mm^2) and
// ~0.41 mm in blue (0.344 at 0.0484 mm^2). So the slab is rendered twice:
// as it is (red, 1-20 mm) and scaled by 0.05 (0.05-1 mm: green and blue),
// seen from 15 mm so that the thin end covers enough pixels.
class SssSlab : public test::RenderFixture {
protected:
    SlabRow measure(double scale, const std::vector<std::string>& overrides) {
        std::vector<std::string> all = {"transmittance.shrink_mm=0", "lights.0.shadow=false",
                                        "characters.0.transform.scale=" + std::to_string(scale)};
        all.insert(all.end(), overrides.begin(), overrides.end());
        load("slab.json", all);
        const int width = 320;
        const int height = 180;
        const Image thickness = render(Aov::Thickness, width, height);
        const Image transmitted = render(Aov::Transmittance, width, height);
        const Image depth = render(Aov::Depth, width, height);
        const Camera& camera = mScene->camera;
        const double tanHalf = std::tan(glm::radians(double(camera.verticalFovDeg)) / 2.0);
        const DiffusionProfile& skin = skinProfile();
        const glm::vec3 radiance = mScene->lights[1].colour * mScene->lights[1].intensity;
        const glm::vec3 albedoRoot = glm::sqrt(mScene->characters[0].material.albedo);
        const double lengthM = 0.2 * scale;
        // E = saturate(dot(-N, L)) with the light straight up: the top face's normal y, whose
        // slope is half the thickness's, 0.5 x 19 mm / 200 mm at any scale.
        const double backLight = 1.0 / std::sqrt(1.0 + 0.0475 * 0.0475);
        SlabRow r;
        const int row = height / 2;
        for (int x = 0; x < width; ++x) {
            const double viewDepthM = depth.at(x, row).r;
            if (viewDepthM <= 0.0 || viewDepthM > camera.positionM.y) continue;  // background
            const double xM = camera.positionM.x + (x + 0.5 - width / 2.0) * 2.0 * viewDepthM * tanHalf / height;
            if (xM < 0.025 * lengthM || xM > 0.975 * lengthM) continue;  // away from the ends
            const double trueMm = scale * (1.0 + 19.0 * xM / lengthM);
            // Thinner than the self rule's distance, a point counts as the surface the light
            // meets and takes nothing (include/Transmittance.glsl); within 10% of it the map's
            // texels and depth filtering may put the point on either side, so it is not checked.
            if (trueMm < 0.9 * DERMIS_SELF_THICKNESS_MM) {
                const glm::vec4 through = transmitted.at(x, row);
                ++r.selfPixels;
                r.selfWorst = std::max(r.selfWorst, double(std::max({through.r, through.g, through.b})));
                continue;
            }
            if (trueMm < 1.1 * DERMIS_SELF_THICKNESS_MM) continue;
            const double measuredMm = thickness.at(x, row).r;
            r.worstThickness = std::max(r.worstThickness, std::abs(measuredMm - trueMm) / trueMm);
            r.thinnestMm = std::min(r.thinnestMm, measuredMm);
            r.thickestMm = std::max(r.thickestMm, measuredMm);
            const glm::vec3 t = skin.transmittance(float(measuredMm));
            for (int c = 0; c < 3; ++c) {
                if (t[c] < kMeasurableT) continue;
                const double expected = double(radiance[c]) * t[c] * albedoRoot[c] * backLight;
                r.worstTransmittance[c] =
                    std::max(r.worstTransmittance[c], std::abs(double(transmitted.at(x, row)[c]) - expected) / expected);
                ++r.checked[c];
            }
        }
        std::printf("slab x%.2f (%.2f-%.2f mm): thickness error %.2f%%; T(s) error R %.3f%% (%d px) G %.3f%% (%d px) "
                    "B %.3f%% (%d px); %d px thinner than the self distance, largest T %.3g\n",
                    scale, r.thinnestMm, r.thickestMm, 100.0 * r.worstThickness, 100.0 * r.worstTransmittance.r,
                    r.checked.r, 100.0 * r.worstTransmittance.g, r.checked.g, 100.0 * r.worstTransmittance.b,
                    r.checked.b, r.selfPixels, r.selfWorst);
        return r;
    }
};

TEST_F(SssSlab, ThicknessMatchesTheWedgeAndEveryChannelFollowsT) {
    const SlabRow thick = measure(1.0, {});
    const SlabRow thin = measure(0.05, {"camera.position_m=[0.005,0.015,0]", "camera.target_m=[0.005,0,0]"});
    // Thickness from the shadow map: 5% (the map's depth is float metres, its texels 0.1 mm
    // apart along the wedge; measured 0.2% on the thick wedge).
    EXPECT_LT(thick.worstThickness, 0.05);
    // T(s) at the measured thickness: 1%. The pass evaluates the same sum of exponentials in
    // float, and its output is half float (0.05%); a weight or variance off by 5% moves T
    // by more than that wherever it is measurable.
    // The thin wedge's first 0.2 mm is the surface the light meets: nothing transmits there
    // (clamping the thickness to 0 instead gave T(0) = 1 along the scan's shoulders).
    EXPECT_GE(thin.selfPixels, 10);  // measured 20
    EXPECT_EQ(thin.selfWorst, 0.0);
    const glm::ivec3 checked = thick.checked + thin.checked;
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(checked[c], 20) << "channel " << c << " is measurable at too few pixels";
        EXPECT_LT(std::max(thick.worstTransmittance[c], thin.worstTransmittance[c]), 0.01) << "channel " << c;
    }
}

TEST_F(Sss, PixelsOutsideTheSssMaskAreBitIdenticalAfterTheBlur) {
    // A skin head beside an opaque blue ball. With mix = 1 and no energy
    // conservation the diffuse AOV is the SSS accumulation itself.
    // Every technique that overwrites or adds into the accumulation must keep to its slot's pixels.
    for (const char* technique : {"gaussians", "separable"}) {
        const std::vector<std::string> overrides = {"characters.0.material.profile=skin", "sss.mix=1",
                                                    "energy_conservation=false", "transmittance.enabled=false",
                                                    std::string("sss.technique=") + technique};
        load("no_sss.json", overrides);
        const Image irradiance = render(Aov::Irradiance, 320, 180);
        const Image diffuse = render(Aov::Diffuse, 320, 180);
        const Image albedo = render(Aov::Albedo, 320, 180);
        const glm::vec3 ball = mScene->characters[1].material.albedo;
        size_t outside = 0;
        size_t inside = 0;
        size_t changedInside = 0;
        for (size_t i = 0; i < irradiance.texels.size(); ++i) {
            const bool background = albedo.texels[i].a < 0.5f;
            const bool isBall = !background && glm::length(glm::vec3(albedo.texels[i]) - ball) < 0.02f;
            if (background || isBall) {
                ++outside;
                ASSERT_EQ(std::memcmp(&irradiance.texels[i], &diffuse.texels[i], 3 * sizeof(float)), 0)
                    << technique << ", texel " << i << ": irradiance " << irradiance.texels[i].r << " " << irradiance.texels[i].g << " "
                    << irradiance.texels[i].b << ", diffuse " << diffuse.texels[i].r << " " << diffuse.texels[i].g << " "
                    << diffuse.texels[i].b;
            } else {
                ++inside;
                if (std::memcmp(&irradiance.texels[i], &diffuse.texels[i], 3 * sizeof(float)) != 0) ++changedInside;
            }
        }
        EXPECT_GT(outside, 1000u);
        EXPECT_GT(inside, 1000u);
        EXPECT_GT(changedInside, inside / 2) << technique << ": the blur should have changed the skin";
    }
}

TEST_F(Sss, NoSssSceneRunsNoSssPass) {
    load("no_sss.json");
    render(Aov::Final, 160, 90);
    for (const PassSummary& s : summary()) {
        if (s.name.rfind("sss", 0) == 0 || s.name == "transmittance") EXPECT_FALSE(s.executed) << s.name;
    }
}

TEST_F(Sss, AlbedoSurvivesTheGBufferWithinATenthOfAPercent) {
    // The G-buffer's albedo is half float: 2^-11 relative rounding (0.05%), under the 0.1% goal.
    // 8-bit sRGB (what it was) reads 0.7980 / 0.5961 / 0.4962 for 0.8 / 0.6 / 0.5 and fails.
    load("furnace.json");
    const Image albedo = render(Aov::Albedo, 64, 36);
    const glm::vec3 expected = mScene->characters[0].material.albedo;
    for (const glm::vec4& t : albedo.texels) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(t[c] / expected[c], 1.0f, 0.001f) << "channel " << c;
    }
}
