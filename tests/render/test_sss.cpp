// Screen-space SSS against closed forms: the furnace, the analytic edge, the
// slab's thickness and transmittance, and the stencil mask.
#include "AnalyticEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "brdf/EnergyTable.h"
#include "include/SharedConstants.glsl"
#include "procedural/ProceduralShapes.h"
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

// The edge on skin slanted by kSlantDeg about the step's line: the plane turns
// about z, so along the screen's x one pixel covers about 1 / cos(slant) times
// the skin it covers face-on. Each pixel of the middle row is compared with
// the exact diffusion of the rendered irradiance row over the skin: pixel j's
// irradiance spread over the stretch of skin [s_j-, s_j+] between the rays
// through its edges (perspective included), by the profile's marginal across
// the row, sum_i w_i (Phi((s - s_j-) / (k sigma_i)) - Phi((s - s_j+) / (k sigma_i))).
// The fit finds the width scale k that fits the row best. Bound 3%: measured
// 1.003 with the width divided by the skin's stretch and the edge test against
// the centre's plane (SssChain.glsl, SLANT); 1.318 with neither (the width from
// depth alone, the bilateral cutting the slope's taps), 1.938 with the plane
// but not the stretch, 0.839 with the stretch but not the plane.
constexpr double kSlantDeg = 60.0;
constexpr double kSlantWidthTolerance = 0.03;
constexpr double kSlantWindowMm = 8.0;  // the row compared; its inputs reach three widest sigmas (8.2 mm) further

TEST_F(SssEdge, SlantedSkinIsBlurredOverItsOwnWidth) {
    load(mScenePath, {"sss.taps=9", "characters.0.transform.rotation_deg=[0,0," + std::to_string(kSlantDeg) + "]"});
    const Image irradiance = render(Aov::Irradiance, kFlatEdgeWidth, kFlatEdgeHeight);
    const Image diffuse = render(Aov::Diffuse, kFlatEdgeWidth, kFlatEdgeHeight);
    const double slant = kSlantDeg * M_PI / 180.0;
    const glm::dvec3 normal(-std::sin(slant), std::cos(slant), 0.0), along(std::cos(slant), std::sin(slant), 0.0);
    const glm::dvec3 camera(0.0, test::kEdgeHeightM, 0.0);
    const double tanHalfFov = std::tan(test::kEdgeFovDeg * M_PI / 360.0);
    const int row = kFlatEdgeHeight / 2;
    // Where the ray through the row's screen x (in pixels) meets the plane, in mm of skin
    // from the step (screen right is +x, the view -y: AnalyticEdge.h's camera).
    auto skinMmAt = [&](double xPx) {
        const double ndcX = xPx / kFlatEdgeWidth * 2.0 - 1.0;
        const double ndcY = 1.0 - (row + 0.5) / kFlatEdgeHeight * 2.0;
        const glm::dvec3 direction(ndcX * tanHalfFov * kFlatEdgeWidth / kFlatEdgeHeight, -1.0, ndcY * tanHalfFov);
        return 1000.0 * glm::dot(camera - glm::dot(normal, camera) / glm::dot(normal, direction) * direction, along);
    };
    const DiffusionProfile& skin = skinProfile();
    const double reachMm = 3.0 * double(skin.largestStdDevMm());
    std::vector<int> onPlane;  // the row's pixels on the plane, away from its rim (20 mm)
    for (int x = 0; x < kFlatEdgeWidth; ++x)
        if (std::abs(skinMmAt(x + 0.5)) < 18.0) onPlane.push_back(x);
    ASSERT_GT(skinMmAt(onPlane.back() + 0.5), kSlantWindowMm + reachMm);
    ASSERT_LT(skinMmAt(onPlane.front() + 0.5), -kSlantWindowMm - reachMm);
    auto rmsAtScale = [&](double k) {
        double sum = 0.0;
        int count = 0;
        for (int x : onPlane) {
            const double s = skinMmAt(x + 0.5);
            if (std::abs(s) > kSlantWindowMm) continue;
            glm::dvec3 expected(0.0);
            for (int j : onPlane) {
                const double lower = skinMmAt(j), upper = skinMmAt(j + 1.0);
                for (const ProfileGaussian& g : skin.gaussians()) {
                    const double sigma = k * std::sqrt(double(g.varianceMm2));
                    const double share = standardNormalCdf((s - lower) / sigma) - standardNormalCdf((s - upper) / sigma);
                    expected += glm::dvec3(g.weight) * share * glm::dvec3(irradiance.at(j, row));
                }
            }
            const glm::dvec3 d = glm::dvec3(diffuse.at(x, row)) - expected;
            sum += glm::dot(d, d);
            count += 3;
        }
        return std::sqrt(sum / count);
    };
    // Golden-section search for the best k in [0.5, 2.5].
    double lo = 0.5, hi = 2.5;
    const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < 40; ++i) {
        const double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
        (rmsAtScale(a) < rmsAtScale(b) ? hi : lo) = (rmsAtScale(a) < rmsAtScale(b) ? b : a);
    }
    const double bestScale = 0.5 * (lo + hi);
    std::printf("slanted %.0f deg: best width scale %.3f (rms %.4f; at 1: %.4f)\n", kSlantDeg, bestScale,
                rmsAtScale(bestScale), rmsAtScale(1.0));
    EXPECT_NEAR(bestScale, 1.0, kSlantWidthTolerance);
}

// Skin hidden behind an occluder: an opaque card (no profile, casting no
// shadow) floats kCardHeightMm over the lit half of the edge scene and hides
// the plane beyond kCardEdgeMm (4.27 mm on the plane, seen from the camera).
// The plane goes on lit under it, so the exact diffuse light of the visible
// pixels between the step and the card is still the closed-form edge
// response; the blur cannot see the hidden skin and must guess it.
// SssEdges.glsl gives a rejected tap's weight to the centre (the skin goes on
// as it is here). Compared from kFromStepMm on, where the albedo map's
// filtering of the step (which the closed form does not have) moves the row
// by under 0.2%. Bound 0.4% of the step: measured 0.20% with the rejected
// weight on the centre; 0.92% with the weights renormalised over the visible
// taps, which pulls the pixels beside the card towards the dark side.
constexpr double kCardHeightMm = 10.0;
constexpr double kCardEdgeMm = 3.0;
constexpr double kFromStepMm = 1.5;
constexpr double kHiddenSkinMaxError = 0.004;

TEST_F(SssEdge, SkinHiddenBehindAnOccluderKeepsTheLightOfItsSide) {
    std::string scene = test::readTextFile(mScenePath);
    const std::string characters = "\"characters\": [";
    const size_t at = scene.find(characters);
    ASSERT_NE(at, std::string::npos);
    char card[512];
    std::snprintf(card, sizeof card,
                  R"({"name": "card", "mesh": {"procedural": "plane"}, "transform": {"translation_m": [%.4f, %.4f, 0], "scale": 0.02},
                      "material": {"albedo": [0.5, 0.5, 0.5], "rho_s": 0, "profile": "none"}}, )",
                  (kCardEdgeMm + 10.0) * 1e-3, kCardHeightMm * 1e-3);
    scene.insert(at + characters.size(), card);
    const std::string cardScene = mDir.file("card.json");
    test::writeTextFile(cardScene, scene);
    load(cardScene, {"sss.taps=9"});
    const Image diffuse = render(Aov::Diffuse, kFlatEdgeWidth, kFlatEdgeHeight);
    const Image objects = render(Aov::Object, kFlatEdgeWidth, kFlatEdgeHeight);

    const double heightMm = test::kEdgeHeightM * 1000.0;
    const double mmPerPixel = 2.0 * heightMm * std::tan(test::kEdgeFovDeg * M_PI / 360.0) / kFlatEdgeHeight;
    // Where the card's edge hides the plane, seen from the camera above x = 0.
    const double hiddenFromMm = kCardEdgeMm * heightMm / (heightMm - kCardHeightMm);
    const int row = kFlatEdgeHeight / 2;
    const DiffusionProfile& skin = skinProfile();
    double maxError = 0.0;
    int compared = 0, cardPixels = 0;
    for (int x = 0; x < kFlatEdgeWidth; ++x) {
        const double xMm = (x + 0.5 - kFlatEdgeWidth / 2.0) * mmPerPixel;
        const bool onCard = std::abs(objects.at(x, row).r - 1.0f) < 0.5f;  // the card is character 0 (+ 1)
        cardPixels += onCard;
        ASSERT_EQ(onCard, xMm > hiddenFromMm + mmPerPixel || (xMm > hiddenFromMm - mmPerPixel && onCard))
            << "the card is not where the test puts it, pixel " << x;
        if (onCard || xMm < kFromStepMm || xMm > hiddenFromMm - mmPerPixel) continue;
        const glm::vec3 expected = skin.edgeResponse(float(xMm));
        for (int c = 0; c < 3; ++c) maxError = std::max(maxError, std::abs(double(diffuse.at(x, row)[c]) - expected[c]));
        ++compared;
    }
    std::printf("skin hidden beyond %.2f mm: %d pixels compared, largest error %.4f of the step (%d card pixels)\n",
                hiddenFromMm, compared, maxError, cardPixels);
    ASSERT_GT(compared, 20);
    EXPECT_LT(maxError, kHiddenSkinMaxError);
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
    glm::dvec3 worstTransmittance{0.0};      // relative, against the model's dense integral, per channel
    double worstClosedForm = 0.0;            // the dense integral against the slab's closed form, thick wedge
    glm::ivec3 checked{0};                   // pixels per channel where T_c >= kMeasurableT
    int selfPixels = 0;                      // thinner than DERMIS_SELF_THICKNESS_MM
    double selfWorst = 0.0;                  // their largest transmitted value (must be 0)
    double thinnestMm = 1e9, thickestMm = 0.0;
};

// A channel is compared where it transmits at least 1%: there the AOV's
// value is a hundred times the float noise of the passes.
constexpr double kMeasurableT = 0.01;

// The wedge of ProceduralShapes.h scaled by `scale`: the slope of each face,
// and its thickness (y from -t/2 to +t/2) over x mm.
constexpr double kWedgeFaceSlope = 0.5 * (kWedgeThickMm - kWedgeThinMm) / (1000.0 * kWedgeLengthM);
double wedgeThicknessMm(double scale, double xMm) {
    return scale * kWedgeThinMm + (kWedgeThickMm - kWedgeThinMm) * xMm / (1000.0 * kWedgeLengthM);
}

// A flat slab h mm thick facing the light: sum_i w_i exp(-h^2 / 2v_i).
glm::dvec3 slabTransmittance(const DiffusionProfile& profile, double hMm) {
    glm::dvec3 t(0.0);
    for (const ProfileGaussian& g : profile.gaussians()) t += glm::dvec3(g.weight) * std::exp(-hMm * hMm / (2.0 * g.varianceMm2));
    return t;
}

double smoothstep(double edge0, double edge1, double x) {
    const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// The transmittance model of include/Transmittance.glsl at the point of the
// wedge's top face over xMm (its centre line, z = 0), with the light straight
// up through the wedge, integrated densely in polar coordinates around the
// point (per Gaussian, 400 radii out to 9 sigma, 128 angles) instead of on
// the shader's six rings of 24 taps. The wedge's faces: y = +-t(x) / 2,
// t(x) = scale (1 + 19 x / length) mm; the first surface over the point
// (x + a, z + b) of the plane across the light is the bottom face there, at
// delta = t(x) / 2 + t(x + a) / 2 along the ray. `centreMm` is the thickness
// the pass read at the point (the centre disc's slab).
glm::dvec3 wedgeTransmittanceModel(const DiffusionProfile& skin, double scale, double xMm, double centreMm) {
    const double lengthMm = 1000.0 * kWedgeLengthM * scale;
    const double halfDepthMm = 500.0 * kWedgeDepthM * scale;
    const double slope = kWedgeFaceSlope;
    const double normalLength = std::sqrt(1.0 + slope * slope);  // top normal (-slope, 1, 0)
    const auto thicknessMm = [&](double at) { return wedgeThicknessMm(scale, at); };
    const auto& gaussians = skin.gaussians();
    const double sigmaMaxMm = std::sqrt(double(gaussians.back().varianceMm2));
    const double centreDiscMm = DERMIS_TRANSMITTANCE_CENTRE_DISC_SIGMAS * sigmaMaxMm;
    const double facing = 1.0 / normalLength;  // saturate(-N.L), the light straight up
    constexpr int kRadii = 400;
    constexpr int kAngles = 128;
    glm::dvec3 sum(0.0);
    for (const ProfileGaussian& g : gaussians) {
        const double v = g.varianceMm2;
        const double outerMm = 9.0 * std::sqrt(v);
        double share = 0.0;  // integral of exp(-delta^2 / 2v) G2(v, rho) x the tap's weight
        for (int i = 0; i < kRadii; ++i) {
            const double r0 = outerMm * i / kRadii, r1 = outerMm * (i + 1) / kRadii;
            const double rho = 0.5 * (r0 + r1);
            const double radialMass = std::exp(-r0 * r0 / (2.0 * v)) - std::exp(-r1 * r1 / (2.0 * v));
            if (rho < centreDiscMm) {
                share += radialMass * facing * std::exp(-centreMm * centreMm / (2.0 * v));
                continue;
            }
            for (int k = 0; k < kAngles; ++k) {
                const double angle = (k + 0.5) * 2.0 * glm::pi<double>() / kAngles;
                const double a = rho * std::cos(angle), b = rho * std::sin(angle);
                if (xMm + a < 0.0 || xMm + a > lengthMm || std::abs(b) > halfDepthMm) continue;  // no surface there
                const double delta = 0.5 * thicknessMm(xMm) + 0.5 * thicknessMm(xMm + a);
                const double behindTangentMm = (slope * a + delta) / normalLength;  // (x - y) . N
                const double own = smoothstep(DERMIS_SELF_THICKNESS_MM, DERMIS_OWN_SURFACE_RAMP_END_MM, behindTangentMm);
                share += radialMass / kAngles * own * std::exp(-delta * delta / (2.0 * v));
            }
        }
        sum += glm::dvec3(g.weight) * share;
    }
    return sum;
}

}  // namespace

// The wedge (1-20 mm thick along x over 0.2 m) seen straight from above, its
// back light shining straight up through it.
// From the skin profile's variances, the slab's T_c(s) >= 1% for s up to
// ~5.5 mm in red (w = 0.078 at 7.41 mm^2), ~1 mm in green and ~0.6 mm in
// blue. So the slab is rendered twice: as it is (red, 1-20 mm) and scaled by
// 0.05 (0.05-1 mm: green and blue), seen from 15 mm so that the thin end
// covers enough pixels.
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
        const double lengthM = kWedgeLengthM * scale;
        SlabRow r;
        const int row = height / 2;
        for (int x = 0; x < width; ++x) {
            const double viewDepthM = depth.at(x, row).r;
            if (viewDepthM <= 0.0 || viewDepthM > camera.positionM.y) continue;  // background
            const double xM = camera.positionM.x + (x + 0.5 - width / 2.0) * 2.0 * viewDepthM * tanHalf / height;
            if (xM < 0.025 * lengthM || xM > 0.975 * lengthM) continue;  // away from the ends
            const double trueMm = wedgeThicknessMm(scale, 1000.0 * xM);
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
            const glm::dvec3 t = wedgeTransmittanceModel(skin, scale, 1000.0 * xM, measuredMm);
            if (trueMm > 4.0 * DERMIS_OWN_SURFACE_RAMP_END_MM) {
                // Every tap lies well behind the tangent plane: the model is a tilted flat back
                // face, sum_i w_i exp(-h^2 / 2v_i) cos(theta), h the distance from the point
                // to that plane (measuredMm cos(theta) across it), theta its tilt.
                const double cosTilt = 1.0 / std::sqrt(1.0 + kWedgeFaceSlope * kWedgeFaceSlope);
                const glm::dvec3 closed = slabTransmittance(skin, measuredMm * cosTilt) * cosTilt;
                for (int c = 0; c < 3; ++c)
                    if (closed[c] >= kMeasurableT) r.worstClosedForm = std::max(r.worstClosedForm, std::abs(t[c] - closed[c]) / closed[c]);
            }
            for (int c = 0; c < 3; ++c) {
                if (t[c] < kMeasurableT) continue;
                const double expected = double(radiance[c]) * t[c] * albedoRoot[c];
                r.worstTransmittance[c] =
                    std::max(r.worstTransmittance[c], std::abs(double(transmitted.at(x, row)[c]) - expected) / expected);
                ++r.checked[c];
            }
        }
        std::printf("slab x%.2f (%.2f-%.2f mm): thickness error %.2f%%; T error R %.3f%% (%d px) G %.3f%% (%d px) "
                    "B %.3f%% (%d px); dense model against the closed form %.3f%%; %d px thinner than the self "
                    "distance, largest T %.3g\n",
                    scale, r.thinnestMm, r.thickestMm, 100.0 * r.worstThickness, 100.0 * r.worstTransmittance.r,
                    r.checked.r, 100.0 * r.worstTransmittance.g, r.checked.g, 100.0 * r.worstTransmittance.b,
                    r.checked.b, 100.0 * r.worstClosedForm, r.selfPixels, r.selfWorst);
        return r;
    }
};

TEST_F(SssSlab, ThicknessMatchesTheWedgeAndEveryChannelFollowsT) {
    const SlabRow thick = measure(1.0, {});
    const SlabRow thin = measure(0.05, {"camera.position_m=[0.005,0.015,0]", "camera.target_m=[0.005,0,0]"});
    // Thickness from the shadow map: 5% (the map's depth is float metres, its texels 0.1 mm
    // apart along the wedge; measured 0.2% on the thick wedge).
    EXPECT_LT(thick.worstThickness, 0.05);
    // The test's dense integral is the slab's closed form on the thick wedge: 0.5% (its
    // quadrature; the centre disc's slab at the point's own thickness differs by less).
    EXPECT_LT(thick.worstClosedForm, 0.005);
    // The thin wedge's first 0.2 mm is the surface the light meets: nothing transmits there
    // (clamping the thickness to 0 instead gave T(0) = 1 along the scan's shoulders).
    EXPECT_GE(thin.selfPixels, 10);  // measured 20
    EXPECT_EQ(thin.selfWorst, 0.0);
    // The pass's six rings of 24 taps against the dense integral. On the thick wedge 1%
    // (measured 0.44% in red; widths scaled by 1.05 read 22%, the widest Gaussian dropped 98%).
    // On the thin wedge the thickness changes 20-fold across the widest Gaussian's reach and
    // crosses the own-surface ramp, where the angular quadrature decides: measured 5.2% (red),
    // 4.5% (green), 0.8% (blue); 48 taps read 4.5%, 3.6%, 0.8% (what is left is the rings' radial
    // spacing). Held to 6% there: 6, 12 and 16 taps per ring read 12.7%, 9.1% and 10.7% in red and
    // 7.3%, 6.7% and 7.8% in green, and fail. TwoPlanesTransmitTheClosedFormOfTheModel holds every
    // channel at these thicknesses to 1%.
    EXPECT_GE(thick.checked.r, 20) << "red is measurable at too few pixels";
    EXPECT_LT(thick.worstTransmittance.r, 0.01);
    for (int c = 0; c < 3; ++c) {
        EXPECT_GE(thin.checked[c], 20) << "channel " << c << " is measurable at too few pixels";
        EXPECT_LT(thin.worstTransmittance[c], 0.06) << "channel " << c;
    }
}

TEST_F(SssSlab, TwoPlanesTransmitTheClosedFormOfTheModel) {
    test::TempDir dir;
    const std::string scene = dir.file("planes.json");
    test::writeTextFile(scene, R"({
      "camera": {"position_m": [0, 0.015, 0], "target_m": [0, 0, 0], "up": [0, 0, -1], "vertical_fov_deg": 50,
                 "near_m": 0.001, "far_m": 1},
      "lights": [{"type": "directional", "direction": [0, 1, 0], "colour": [1, 0.95, 0.9], "intensity": 3, "shadow": true}],
      "characters": [
        {"name": "top", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.06},
         "material": {"albedo": [0.85, 0.7, 0.6], "roughness": 0.3, "rho_s": 0.18, "profile": "skin"}},
        {"name": "bottom", "mesh": {"procedural": "plane"}, "transform": {"scale": 0.06, "rotation_deg": [180, 0, 0]},
         "material": {"albedo": [0.85, 0.7, 0.6], "roughness": 0.3, "rho_s": 0.18, "profile": "skin"}}
      ],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "ssao": {"enabled": false}, "shadow": {"map_size": 2048},
                   "transmittance": {"shrink_mm": 0}}
    })");
    const DiffusionProfile& skin = skinProfile();
    const double sigmaMaxMm = std::sqrt(double(skin.gaussians().back().varianceMm2));
    const double centreDiscMm = DERMIS_TRANSMITTANCE_CENTRE_DISC_SIGMAS * sigmaMaxMm;
    glm::dvec3 worst(0.0);
    glm::ivec3 checked(0);
    for (double tMm : {0.3, 0.45, 0.6, 0.9, 1.5}) {
        load(scene, {"characters.1.transform.translation_m=[0," + std::to_string(-tMm * 1e-3) + ",0]"});
        const glm::vec3 radiance = mScene->lights[0].colour * mScene->lights[0].intensity;
        const glm::dvec3 albedoRoot = glm::sqrt(glm::dvec3(mScene->characters[0].material.albedo));
        const double ramp = smoothstep(DERMIS_SELF_THICKNESS_MM, DERMIS_OWN_SURFACE_RAMP_END_MM, tMm);
        glm::dvec3 closed(0.0);
        for (const ProfileGaussian& g : skin.gaussians()) {
            const double centreMass = 1.0 - std::exp(-centreDiscMm * centreDiscMm / (2.0 * g.varianceMm2));
            closed += glm::dvec3(g.weight) * std::exp(-tMm * tMm / (2.0 * g.varianceMm2)) *
                      (centreMass + (1.0 - centreMass) * ramp);
        }
        const Image transmitted = render(Aov::Transmittance, 160, 90);
        glm::dvec3 worstHere(0.0);
        // The middle half of the frame: its taps (out to 2.6 widest sigma, 7 mm) stay on the planes.
        for (int y = 23; y < 68; ++y) {
            for (int x = 40; x < 120; ++x) {
                for (int c = 0; c < 3; ++c) {
                    if (closed[c] < kMeasurableT) continue;
                    const double expected = double(radiance[c]) * closed[c] * albedoRoot[c];
                    worstHere[c] = std::max(worstHere[c], std::abs(double(transmitted.at(x, y)[c]) - expected) / expected);
                    ++checked[c];
                }
            }
        }
        std::printf("planes %.2f mm apart: closed form T = %.4f %.4f %.4f, worst error R %.3f%% G %.3f%% B %.3f%%\n", tMm,
                    closed.r, closed.g, closed.b, 100.0 * worstHere.r, 100.0 * worstHere.g, 100.0 * worstHere.b);
        worst = glm::max(worst, worstHere);
    }
    // 1%: measured 0.49% at most (the float sums and the half-float output); the widths
    // scaled by 1.05 read up to 26% (blue at 0.6 mm), the widest Gaussian dropped up to 24% (red).
    for (int c = 0; c < 3; ++c) {
        EXPECT_GT(checked[c], 1000) << "channel " << c;
        EXPECT_LT(worst[c], 0.01) << "channel " << c;
    }

    // Seen from 0.6 m the widest Gaussian spans 0.45 px (under DERMIS_TRANSMITTANCE_SLAB_BELOW_PX):
    // the slab's closed form sum_i w_i exp(-t^2 / 2v_i), without the ramp, stands in.
    const double tMm = 0.45;
    load(scene, {"characters.1.transform.translation_m=[0," + std::to_string(-tMm * 1e-3) + ",0]",
                 "camera.position_m=[0,0.6,0]"});
    const Image far = render(Aov::Transmittance, 160, 90);
    const glm::vec3 radiance = mScene->lights[0].colour * mScene->lights[0].intensity;
    const glm::dvec3 albedoRoot = glm::sqrt(glm::dvec3(mScene->characters[0].material.albedo));
    const glm::dvec3 slab = slabTransmittance(skin, tMm);
    const glm::vec4 centre = far.at(80, 45);
    for (int c = 0; c < 3; ++c) {
        const double expected = double(radiance[c]) * slab[c] * albedoRoot[c];
        EXPECT_NEAR(centre[c], expected, 0.01 * expected) << "channel " << c << " seen from afar";
    }
}

// A ball 20 cm across lit from behind and to the side: no light goes
// through it, and beside its terminator the lit surface the shadow map sees
// is the pixel's own, whose light the SSS blur carries. Without the model's
// own-surface rules (include/Transmittance.glsl) the band beside the
// terminator took up to 0.39 of the light's 2 (the head scan's shoulders:
// scatter error 1.16% -> 13.7%); measured with them 0.0022, at 34 pixels.
TEST_F(SssSlab, AThickBallTakesNoTransmittedLightBesideItsTerminator) {
    test::TempDir dir;
    const std::string scene = dir.file("ball.json");
    test::writeTextFile(scene, R"({
      "camera": {"position_m": [0, 0, 0.5], "target_m": [0, 0, 0], "vertical_fov_deg": 30},
      "lights": [{"type": "directional", "direction": [0.8, 0, 0.6], "intensity": 2, "shadow": true}],
      "characters": [{"name": "ball", "mesh": {"procedural": "sphere"}, "material": {"profile": "skin"}}],
      "background": {"colour": [0, 0, 0]},
      "settings": {"ambient": [0, 0, 0], "ssao": {"enabled": false}}
    })");
    load(scene);
    const Image transmitted = render(Aov::Transmittance, 160, 90);
    ASSERT_NE(pass("transmittance"), nullptr);
    EXPECT_TRUE(pass("transmittance")->executed);
    const Image thickness = render(Aov::Thickness, 160, 90);
    float largest = 0.0f;
    int inShadow = 0;
    for (size_t i = 0; i < transmitted.texels.size(); ++i) {
        const glm::vec4 t = transmitted.texels[i];
        largest = std::max({largest, t.r, t.g, t.b});
        inShadow += thickness.texels[i].r > 0.0f;
    }
    std::printf("largest transmitted %.4f over %d shadowed pixels\n", largest, inShadow);
    EXPECT_GT(inShadow, 1000) << "the light must be behind most of the ball";
    // 1% of the light's radiance: ten times what is measured, a fortieth of the failure.
    EXPECT_LT(largest, 0.02f);
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
