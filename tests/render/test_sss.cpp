// Screen-space SSS against closed forms: the furnace, the analytic edge, the
// slab's thickness and transmittance, and the stencil mask.
#include "AnalyticEdge.h"
#include "RenderFixture.h"
#include "TestSupport.h"

#include "sss/DiffusionProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace dermis;

namespace {

class Sss : public test::RenderFixture {};

constexpr int kTapCounts[] = {5, 7, 9, 13, 17};

// The analytic edge (AnalyticEdge.h) at this size.
constexpr int kEdgeWidth = 640;
constexpr int kEdgeHeight = 360;

}  // namespace

TEST_F(Sss, FurnaceUniformLightStaysUniformForEveryTapCount) {
    for (const char* blur : {"bilateral", "control"}) {
        for (int taps : kTapCounts) {
            load("furnace.json", {"sss.taps=" + std::to_string(taps), std::string("sss.blur=") + blur});
            const Image image = render(Aov::Diffuse, 160, 90);
            ASSERT_EQ(test::countNonFinite(image), 0u);
            load("furnace.json", {"sss.enabled=false"});
            const Image unblurred = render(Aov::Diffuse, 160, 90);
            double worst = 0.0;
            for (size_t i = 0; i < image.texels.size(); ++i) {
                for (int c = 0; c < 3; ++c) {
                    const double reference = unblurred.texels[i][c];
                    ASSERT_GT(reference, 0.05);
                    worst = std::max(worst, std::abs(image.texels[i][c] - reference) / reference);
                }
            }
            std::printf("furnace %-9s %2d taps: largest relative change %.5f\n", blur, taps, worst);
            EXPECT_LT(worst, 0.005) << blur << " " << taps << " taps";
        }
    }
}

TEST_F(Sss, AnalyticEdgeMatchesSumOfGaussianCdfs) {
    test::TempDir dir;
    const std::string scene = test::writeEdgeScene(dir);
    for (int taps : kTapCounts) {
        load(scene, {"sss.taps=" + std::to_string(taps), "sss.min_width_px=0"});
        const test::EdgeError error = test::edgeError(render(Aov::Diffuse, kEdgeWidth, kEdgeHeight), kEdgeWidth, kEdgeHeight);
        const double maxError = error.max;
        const double rms = error.rms;
        std::printf("analytic edge, %2d taps: max error %.4f, RMS %.4f (of a unit step)\n", taps, maxError, rms);
        // Bounds from the measured errors with margin: taps are nearest-texel
        // (SssBlur.glsl), so a few taps spread over a narrow Gaussian miss
        // the step by up to a pixel.
        EXPECT_LT(maxError, taps < 9 ? 0.2 : 0.08) << taps << " taps";
        EXPECT_LT(rms, 0.01) << taps << " taps";
    }
}

TEST_F(Sss, SlabThicknessMatchesTheWedgeAndTransmittanceFollowsT) {
    // Camera straight above the wedge; its back light shines straight up
    // through it, so the thickness along the light is the wedge's thickness.
    load("slab.json", {"transmittance.shrink_mm=0", "lights.0.shadow=false"});
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

    double worstThickness = 0.0;
    double worstTransmittance = 0.0;
    int checked = 0;
    const int row = height / 2;
    for (int x = 0; x < width; ++x) {
        const double viewDepthM = depth.at(x, row).r;
        if (viewDepthM > 0.5) continue;  // background
        const double xM = camera.positionM.x + (x + 0.5 - width / 2.0) * 2.0 * viewDepthM * tanHalf / height;
        if (xM < 0.005 || xM > 0.195) continue;  // away from the ends
        const double trueMm = 1.0 + 19.0 * xM / 0.2;
        const double measuredMm = thickness.at(x, row).r;
        worstThickness = std::max(worstThickness, std::abs(measuredMm - trueMm) / trueMm);
        const glm::vec3 expected = radiance * skin.transmittance(float(measuredMm)) * albedoRoot;
        for (int c = 0; c < 3; ++c) {
            if (expected[c] < 1e-3f) continue;
            worstTransmittance =
                std::max(worstTransmittance, std::abs(double(transmitted.at(x, row)[c]) - expected[c]) / expected[c]);
        }
        ++checked;
    }
    std::printf("slab: %d pixels, worst thickness error %.2f%%, worst T(s) error %.2f%%\n", checked,
                100.0 * worstThickness, 100.0 * worstTransmittance);
    EXPECT_GT(checked, 100);
    EXPECT_LT(worstThickness, 0.05);
    EXPECT_LT(worstTransmittance, 0.02);
}

TEST_F(Sss, PixelsOutsideTheSssMaskAreBitIdenticalAfterTheBlur) {
    // A skin head beside an opaque blue ball. With mix = 1 and no energy
    // conservation the diffuse AOV is the SSS accumulation itself.
    const std::vector<std::string> overrides = {"characters.0.material.profile=skin", "sss.mix=1",
                                                "energy_conservation=false", "transmittance.enabled=false"};
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
                << "texel " << i << ": irradiance " << irradiance.texels[i].r << " " << irradiance.texels[i].g << " "
                << irradiance.texels[i].b << ", diffuse " << diffuse.texels[i].r << " " << diffuse.texels[i].g << " "
                << diffuse.texels[i].b;
        } else {
            ++inside;
            if (std::memcmp(&irradiance.texels[i], &diffuse.texels[i], 3 * sizeof(float)) != 0) ++changedInside;
        }
    }
    EXPECT_GT(outside, 1000u);
    EXPECT_GT(inside, 1000u);
    EXPECT_GT(changedInside, inside / 2) << "the blur should have changed the skin";
}

TEST_F(Sss, NoSssSceneRunsNoSssPass) {
    load("no_sss.json");
    render(Aov::Final, 160, 90);
    for (const PassSummary& s : summary()) {
        if (s.name.rfind("sss", 0) == 0 || s.name == "transmittance") EXPECT_FALSE(s.executed) << s.name;
    }
}

TEST_F(Sss, AlbedoSurvivesTheSrgbGBufferExactly) {
    // The G-buffer stores albedo as sRGB: the write must encode (GL_FRAMEBUFFER_SRGB)
    // so the read's decode gives back the linear value, within 8-bit steps.
    load("furnace.json");
    const Image albedo = render(Aov::Albedo, 64, 36);
    const glm::vec3 expected = mScene->characters[0].material.albedo;
    for (const glm::vec4& t : albedo.texels) {
        for (int c = 0; c < 3; ++c) ASSERT_NEAR(t[c], expected[c], 0.004f);
    }
}
