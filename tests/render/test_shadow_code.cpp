// The programs that read shadow maps compile only the filters the frame's
// lights use (plan/LightSetup.h ShadowCode, include/Shadows.glsl), and the
// lighting pass the code of the techniques that scatter in it only where a
// slot does (LIGHTING_SCATTER). Each such frame must draw what the programs
// holding every filter and technique draw: the same scene rendered by two
// renderers, one with Programs::build(true), one with build(false).
#include "RenderFixture.h"
#include "TestSupport.h"

#include "plan/LightSetup.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

using namespace dermis;
using namespace dermis::test;

namespace {

class ShadowCodeTest : public GlTest {
protected:
    // The largest channel difference between the two renderers' frames
    // (AOVs Final and Diffuse), relative to the frame's largest value.
    double largestRelativeDifference(const std::vector<std::string>& overrides, ShadowCode expected,
                                     const std::string& sceneFile = "default.json") {
        auto scene = loadScene(contentScene(sceneFile), overrides);
        EXPECT_TRUE(scene.ok()) << scene.error().message();
        if (!scene.ok()) return INFINITY;
        const LightSetup lights = setupLights(scene->lights, Bounds{}, scene->settings.shadow);
        EXPECT_EQ(int(lights.shadowCode), int(expected));
        std::vector<std::unique_ptr<Renderer>> renderers;
        for (bool specialize : {true, false}) {
            auto programs = Programs::build(specialize);
            EXPECT_TRUE(programs.ok()) << programs.error().message();
            if (!programs.ok()) return INFINITY;
            auto renderer = Renderer::create(*scene, std::make_shared<Programs>(std::move(*programs)));
            EXPECT_TRUE(renderer.ok()) << renderer.error().message();
            if (!renderer.ok()) return INFINITY;
            renderers.push_back(std::move(*renderer));
        }
        double worst = 0.0;
        for (Aov aov : {Aov::Final, Aov::Diffuse}) {
            std::vector<Image> frames;
            for (const auto& renderer : renderers) {
                const Status status = renderer->renderFrame({160, 90, aov});
                EXPECT_TRUE(status.ok()) << status.error().message();
                auto image = renderer->readOutput();
                EXPECT_TRUE(image.ok());
                if (!image.ok()) return INFINITY;
                frames.push_back(std::move(*image));
            }
            double largest = 0.0;
            double difference = 0.0;
            for (size_t i = 0; i < frames[0].texels.size(); ++i) {
                for (int c = 0; c < 3; ++c) {
                    largest = std::max(largest, double(std::fabs(frames[1].texels[i][c])));
                    difference = std::max(difference, double(std::fabs(frames[0].texels[i][c] - frames[1].texels[i][c])));
                }
            }
            EXPECT_GT(largest, 0.0) << "a black frame compares equal to anything";
            worst = std::max(worst, difference / std::max(largest, 1e-30));
        }
        return worst;
    }
};

// The code a light set needs follows include/Shadows.glsl's branches: the
// bilinear test for delta lights with 2-D maps under the PCSS filter, PCSS
// for lights with a size, the rest for other filters and delta cube maps.
TEST(ShadowCode, EachLightSetGetsTheLeastCodeThatCoversIt) {
    auto light = [](LightType type, float sizeDegOrM) {
        Light l;
        l.type = type;
        l.castsShadow = true;
        (type == LightType::Directional ? l.angularDiameterDeg : l.radiusM) = sizeDegOrM;
        return l;
    };
    const ShadowSettings pcss;
    ShadowSettings poisson;
    poisson.filter = ShadowFilter::Poisson;
    auto code = [](const std::vector<Light>& lights, const ShadowSettings& s) {
        return setupLights(lights, Bounds{}, s).shadowCode;
    };
    EXPECT_EQ(code({}, pcss), ShadowCode::HardEdges);
    EXPECT_EQ(code({light(LightType::Directional, 0), light(LightType::Spot, 0)}, pcss), ShadowCode::HardEdges);
    EXPECT_EQ(code({light(LightType::Directional, 2), light(LightType::Spot, 0)}, pcss), ShadowCode::SoftEdges);
    EXPECT_EQ(code({light(LightType::Point, 0.02f)}, pcss), ShadowCode::SoftEdges);
    EXPECT_EQ(code({light(LightType::Spot, 0), light(LightType::Point, 0)}, pcss), ShadowCode::EveryFilter);
    EXPECT_EQ(code({light(LightType::Directional, 0)}, poisson), ShadowCode::EveryFilter);
    Light unshadowed = light(LightType::Point, 0);
    unshadowed.castsShadow = false;
    EXPECT_EQ(code({light(LightType::Directional, 0), unshadowed}, pcss), ShadowCode::HardEdges);
}

// Bound: the programs differ only in code that does not run for these lights
// and pixels, so the frames are the same but for the compiler's choice of
// fused multiply-adds, at most a unit in the last place of a half float
// (measured: 0 in every case). A wrong choice changes whole penumbrae and
// terminators: the hard edges for the 4-degree light read 0.38 (ss) and 0.31
// (ts); the lighting pass without its scatter code where the slot uses the
// pre-integrated technique, 0.37; the crowd's pre-integrated heads left
// without their second draw, 0.096.
constexpr double kSameFrame = 1e-3;

TEST_F(ShadowCodeTest, DeltaLightsDrawTheSameWithTheHardEdgesAlone) {
    EXPECT_LE(largestRelativeDifference({}, ShadowCode::HardEdges), kSameFrame);
    EXPECT_LE(largestRelativeDifference({"mode=ts"}, ShadowCode::HardEdges), kSameFrame);
}

TEST_F(ShadowCodeTest, ASizedLightDrawsTheSameWithTheSoftEdgesAlone) {
    const std::string sized = "lights.0.angular_diameter_deg=4";
    EXPECT_LE(largestRelativeDifference({sized}, ShadowCode::SoftEdges), kSameFrame);
    EXPECT_LE(largestRelativeDifference({sized, "mode=ts"}, ShadowCode::SoftEdges), kSameFrame);
}

TEST_F(ShadowCodeTest, TheLightingPassScattersTheSameWithItsScatterCodeOnlyWhereASlotNeedsIt) {
    EXPECT_LE(largestRelativeDifference({"settings.sss.technique=preintegrated"}, ShadowCode::HardEdges), kSameFrame);
    EXPECT_LE(largestRelativeDifference({"settings.sss.enabled=false"}, ShadowCode::HardEdges), kSameFrame);
    // The budget crowd mixes slots: the far heads pre-integrated, the others blurred. The
    // pass draws the frame without the scatter code and those heads' rectangles again with it.
    EXPECT_LE(largestRelativeDifference({}, ShadowCode::HardEdges, "crowd8_mixed.json"), kSameFrame);
}

}  // namespace

namespace {

// A specialized program that fails to build gives way to the one with every
// filter (which draws the same image), and the failure is logged once, with
// the file; the other specialized programs still build, each its own.
TEST_F(ShadowCodeTest, ASpecializedProgramThatFailsGivesWayToTheFullOne) {
    auto programs = Programs::build();
    ASSERT_TRUE(programs.ok()) << programs.error().message();
    ShadowedPrograms& lighting = programs->lighting.plain;
    const GLuint full = lighting.everyFilter.get(false);
    ASSERT_NE(full, 0u);
    lighting.specialized[size_t(ShadowCode::HardEdges)][0] =
        gl::LazyProgram(gl::ProgramSource{"fullscreen.vert", "no_such_shader.frag", {}, "", {}});
    testing::internal::CaptureStderr();
    EXPECT_EQ(lighting.get(false, ShadowCode::HardEdges), full);
    const std::string firstLog = testing::internal::GetCapturedStderr();
    EXPECT_NE(firstLog.find("no_such_shader.frag"), std::string::npos) << firstLog;
    testing::internal::CaptureStderr();
    EXPECT_EQ(lighting.get(false, ShadowCode::HardEdges), full);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "built and logged once";
    const GLuint soft = lighting.get(false, ShadowCode::SoftEdges);
    EXPECT_NE(soft, 0u);
    EXPECT_NE(soft, full);
}

}  // namespace
