// What the texture-space mode decides to run, on the CPU alone.
#include "plan/ScreenFootprint.h"
#include "plan/TsPlan.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace dermis;

namespace {

const Bounds kHeadBounds{glm::vec3(-0.1f, -0.19f, -0.12f), glm::vec3(0.1f, 0.15f, 0.13f)};
constexpr float kHeadMmPerUv = 600.0f;

Scene defaultScene(const std::vector<std::string>& overrides = {}) {
    auto scene = loadScene(std::string(DERMIS_SOURCE_CONTENT_DIR) + "/scenes/default.json", overrides);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    return scene.ok() ? *scene : Scene{};
}

TsPlan plan(const Scene& scene, int width = 640, int height = 360, Bounds bounds = kHeadBounds,
            float uvlessSurfaceFraction = 0.0f, float uvOverlapFraction = 0.0f, float mmPerUv = kHeadMmPerUv,
            float uvCoverageFraction = 1.0f) {
    std::vector<TsCharacterInput> inputs(
        scene.characters.size(),
        {bounds, mmPerUv, 0.5f * mmPerUv, uvlessSurfaceFraction, uvOverlapFraction, uvCoverageFraction});
    const LightSetup lights = setupLights(scene.lights, bounds, scene.settings.shadow);
    auto result = planTextureSpace(scene, inputs, makeViewParams(scene.camera, width, height), lights);
    EXPECT_TRUE(result.ok()) << result.error().message();
    return result.ok() ? *result : TsPlan{};
}

}  // namespace

TEST(TsPlan, TextureSizeIsTheNearestPowerOfTwoWithinTheLimits) {
    EXPECT_EQ(tsTextureSize(1000.0f, 256, 2048), 1024);
    EXPECT_EQ(tsTextureSize(1400.0f, 256, 2048), 1024);
    EXPECT_EQ(tsTextureSize(1500.0f, 256, 2048), 2048);
    EXPECT_EQ(tsTextureSize(100000.0f, 256, 2048), 2048);
    EXPECT_EQ(tsTextureSize(10.0f, 256, 2048), 256);
    EXPECT_EQ(tsTextureSize(0.0f, 256, 2048), 256);
    EXPECT_EQ(tsTextureSize(NAN, 256, 2048), 256);
    EXPECT_EQ(tsTextureSize(INFINITY, 256, 2048), 256);
    EXPECT_EQ(tsTextureSize(1e30f, 64, 4096), 4096);
}

TEST(TsPlan, VisibleSkinHeadTakesFiveIncrementalBlurs) {
    const TsPlan p = plan(defaultScene());
    ASSERT_EQ(p.characters.size(), 1u);
    const TsCharacterPlan& head = p.characters[0];
    EXPECT_TRUE(head.visible);
    EXPECT_EQ(head.label, "head");
    ASSERT_EQ(head.gaussians.size(), 6u);
    ASSERT_EQ(head.steps.size(), 6u);
    const auto& skin = skinProfile().gaussians();
    float total = 0.0f;
    int blurred = 0;
    for (size_t i = 0; i < head.steps.size(); ++i) {
        EXPECT_EQ(head.steps[i].gaussian, int(i));
        EXPECT_FLOAT_EQ(head.steps[i].stepVarianceMm2, skin[i].varianceMm2 - (i == 0 ? 0.0f : skin[i - 1].varianceMm2));
        total += head.steps[i].stepVarianceMm2;
        blurred += head.steps[i].skipped ? 0 : 1;
    }
    // The incremental steps add up to the widest Gaussian (Chappuis 2011 §2.2.4),
    // and Gaussian 0 is the irradiance itself: five blurs.
    EXPECT_NEAR(total, skin[5].varianceMm2, 1e-5f);
    EXPECT_TRUE(head.steps[0].skipped);
    EXPECT_EQ(blurred, 5);
    EXPECT_GE(head.size, 256);
    EXPECT_LE(head.size, 2048);
    EXPECT_EQ(head.size & (head.size - 1), 0);
}

TEST(TsPlan, SizeFollowsScreenCoverage) {
    const Scene scene = defaultScene();
    const int small = plan(scene, 320, 180).characters[0].size;
    const int large = plan(scene, 1280, 720).characters[0].size;
    EXPECT_EQ(large, 4 * small > 2048 ? 2048 : 4 * small);
    EXPECT_LT(small, large);
    const TsPlan capped = plan(defaultScene({"ts.max_size=512"}), 1280, 720);
    EXPECT_EQ(capped.characters[0].size, 512);
    const TsPlan floored = plan(defaultScene({"ts.min_size=1024"}), 64, 36);
    EXPECT_EQ(floored.characters[0].size, 1024);
}

// An atlas whose charts cover 5% of the UV square, its median stretch (10 m
// per UV unit) inflated by many small charts, on a head-sized surface: by
// texel density alone it gets 2048 or more at every distance, 17 to 86 texels
// per pixel of its screen rectangle. Sized by coverage, the texels that hold surface
// (size^2 x coverage) stay within a factor of two (the power-of-two rounding
// of the side) of kTexelsPerCoveredPixel per pixel of its screen rectangle,
// from 0.4 m to 3.2 m away, so the cost follows the coverage.
TEST(TsPlan, AtlasLayoutIsSizedByItsScreenCoverage) {
    constexpr float kAtlasCoverage = 0.05f, kAtlasMmPerUv = 10000.0f;
    for (float distanceM : {0.4f, 0.8f, 1.6f, 3.2f}) {
        const std::string eye = "camera.position_m=[0," + std::to_string(0.0f) + "," + std::to_string(distanceM) + "]";
        const Scene scene = defaultScene({eye, "camera.target_m=[0,0,0]", "ts.min_size=64", "ts.max_size=4096"});
        const ViewParams view = makeViewParams(scene.camera, 640, 360);
        const ScreenFootprint footprint = screenFootprint(kHeadBounds, view);
        const float rectanglePixels = footprint.unclippedPixels;
        const int size = plan(scene, 640, 360, kHeadBounds, 0.0f, 0.0f, kAtlasMmPerUv, kAtlasCoverage).characters[0].size;
        const float texelsPerPixel = float(size) * float(size) * kAtlasCoverage / rectanglePixels;
        EXPECT_GE(texelsPerPixel, 0.5f * kTexelsPerCoveredPixel) << distanceM << " m: size " << size;
        EXPECT_LE(texelsPerPixel, 2.0f * kTexelsPerCoveredPixel) << distanceM << " m: size " << size;
        // A layout that fills the square at the same density still gets the density's size when that is smaller.
        const int filled = plan(scene, 640, 360, kHeadBounds, 0.0f, 0.0f, kHeadMmPerUv, 1.0f).characters[0].size;
        EXPECT_LE(filled, tsTextureSize(kHeadMmPerUv * view.pixelsPerMetreAtUnitDepth() * 1e-3f / footprint.nearestViewDepthM,
                                        64, 4096));
    }
}

TEST(TsPlan, OffScreenCharacterIsInvisibleAndSkipsEveryStep) {
    const Bounds behindCamera{glm::vec3(0.5f, 0.0f, 2.0f), glm::vec3(0.7f, 0.3f, 2.2f)};
    const TsPlan p = plan(defaultScene(), 640, 360, behindCamera);
    ASSERT_EQ(p.characters.size(), 1u);
    EXPECT_FALSE(p.characters[0].visible);
    EXPECT_FALSE(p.anyRuns());
    for (const TsStep& step : p.characters[0].steps) EXPECT_TRUE(step.skipped);
}

TEST(TsPlan, DisabledSssMakesEveryCharacterInvisible) {
    const TsPlan p = plan(defaultScene({"sss.enabled=false"}));
    EXPECT_FALSE(p.anyRuns());
}

TEST(TsPlan, DroppedGaussiansFoldIntoTheWidestKept) {
    const TsPlan p = plan(defaultScene({"sss.gaussians=3", "sss.width_scale=2"}));
    const TsCharacterPlan& head = p.characters[0];
    ASSERT_EQ(head.gaussians.size(), 3u);
    ASSERT_EQ(head.steps.size(), 3u);
    glm::vec3 sum(0.0f);
    for (const glm::vec4& g : head.gaussians) sum += glm::vec3(g);
    EXPECT_NEAR(sum.r, 1.0f, 1e-5f);
    EXPECT_NEAR(sum.g, 1.0f, 1e-5f);
    EXPECT_NEAR(sum.b, 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(head.gaussians[2].a, 4.0f * skinProfile().gaussians()[2].varianceMm2);
}

TEST(TsPlan, NarrowGaussiansAreSkippedAtLowResolution) {
    // At 64 texels over 300 mm a texel is ~5 mm: only the widest skin Gaussian spans half a texel.
    const TsPlan p = plan(defaultScene({"ts.min_size=64", "ts.max_size=64"}));
    const TsCharacterPlan& head = p.characters[0];
    int blurred = 0;
    for (const TsStep& step : head.steps) {
        EXPECT_EQ(step.skipped, step.widthTexels < kMinStepTexels);
        blurred += step.skipped ? 0 : 1;
    }
    EXPECT_LT(blurred, 5);
    EXPECT_FALSE(head.steps.back().skipped);
}

TEST(TsPlan, CloseUpsBlurGaussianZeroToo) {
    // 40 mm of skin filling a 360-pixel-high view at 2048 texels: 0.02 mm a texel.
    Scene scene = defaultScene({"ts.min_size=2048"});
    const Bounds small{glm::vec3(-0.02f, -0.001f, -0.02f), glm::vec3(0.02f, 0.001f, 0.02f)};
    scene.camera.positionM = glm::vec3(0.0f, 0.0f, 0.05f);
    scene.camera.targetM = glm::vec3(0.0f);
    std::vector<TsCharacterInput> inputs(1, {small, 40.0f, 40.0f});
    auto p = planTextureSpace(scene, inputs, makeViewParams(scene.camera, 640, 360), LightSetup{});
    ASSERT_TRUE(p.ok());
    EXPECT_FALSE(p->characters[0].steps[0].skipped);
    EXPECT_GT(p->characters[0].steps[0].widthTexels, 3.0f);
}

TEST(TsPlan, TranslucentShadowMapUsesTheShadowedBackLight) {
    // default.json: light 0 lights the face, light 1 (a shadowed spot) is behind the head.
    TsPlan p = plan(defaultScene({"ts.tsm=true"}));
    EXPECT_EQ(p.characters[0].tsmLight, 1);
    EXPECT_GE(p.characters[0].tsmSize, kMinTsmSize);
    EXPECT_LE(p.characters[0].tsmSize, kMaxTsmSize);
    EXPECT_FALSE(p.characters[0].tsmAlongAxis);
    // The head's centre projects into the middle of the map.
    const glm::vec4 clip = p.characters[0].tsmClipFromWorld * glm::vec4(kHeadBounds.centre(), 1.0f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-4f);
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-4f);
    EXPECT_EQ(plan(defaultScene({"ts.tsm=false"})).characters[0].tsmLight, -1);
    EXPECT_EQ(plan(defaultScene()).characters[0].tsmLight, -1) << "the TSM is off by default";
    EXPECT_EQ(plan(defaultScene({"ts.tsm=true", "transmittance.enabled=false"})).characters[0].tsmLight, -1);
    EXPECT_EQ(plan(defaultScene({"ts.tsm=true", "lights.1.shadow=false"})).characters[0].tsmLight, -1);
    // Seen from behind, the key light is the back light.
    EXPECT_EQ(plan(defaultScene({"ts.tsm=true", "camera.position_m=[-0.3,0.1,-0.5]"})).characters[0].tsmLight, 0);
}

TEST(TsPlan, OpaqueCharactersHaveNoPlanAndLabelsAreUnique) {
    Scene scene = defaultScene();
    scene.characters.push_back(scene.characters[0]);
    scene.characters.push_back(scene.characters[0]);
    scene.characters[1].material.profile = "none";
    const TsPlan p = plan(scene);
    ASSERT_EQ(p.characters.size(), 2u);
    EXPECT_EQ(p.characters[0].character, 0);
    EXPECT_EQ(p.characters[1].character, 2);
    EXPECT_EQ(p.characters[0].label, "head #0");
    EXPECT_EQ(p.characters[1].label, "head #2");
}

TEST(TsPlan, UnknownProfileIsAnError) {
    Scene scene = defaultScene();
    scene.characters[0].material.profile = "jade";
    std::vector<TsCharacterInput> inputs(1, {kHeadBounds, kHeadMmPerUv, 300.0f});
    auto result = planTextureSpace(scene, inputs, makeViewParams(scene.camera, 64, 36), LightSetup{});
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.error().what.find("jade"), std::string::npos);
}

// plan/TsPlan.h: more than kMaxUvlessSurfaceFraction of the surface without
// UV area falls back to screen space, with every step skipped and the reason.
TEST(TsPlan, CharacterWithoutUvAreaFallsBackToScreenSpace) {
    const TsPlan bare = plan(defaultScene(), 640, 360, kHeadBounds, 1.0f);
    ASSERT_EQ(bare.characters.size(), 1u);
    const TsCharacterPlan& c = bare.characters[0];
    EXPECT_TRUE(c.visible);
    EXPECT_FALSE(c.runs());
    EXPECT_FALSE(bare.anyRuns());
    EXPECT_TRUE(bare.anyVisibleFallback());
    EXPECT_EQ(c.skipReason(),
              "falls back to screen space: 100% of its surface has no UV area (limit 1%; the mesh has no TEXCOORD_0, "
              "or all UVs equal)");
    for (const TsStep& step : c.steps) EXPECT_TRUE(step.skipped);

    const TsPlan partly = plan(defaultScene(), 640, 360, kHeadBounds, 0.25f);
    EXPECT_EQ(partly.characters[0].fallback, "25% of its surface has no UV area (limit 1%)");

    const TsPlan fine = plan(defaultScene(), 640, 360, kHeadBounds, 0.5f * kMaxUvlessSurfaceFraction);
    EXPECT_TRUE(fine.characters[0].runs());
    EXPECT_FALSE(fine.anyVisibleFallback());
    EXPECT_EQ(fine.characters[0].skipReason(), "");
}

// More than kMaxUvOverlapFraction of the covered texels covered twice falls back too.
TEST(TsPlan, CharacterWithOverlappingUvsFallsBackToScreenSpace) {
    const TsPlan overlapped = plan(defaultScene(), 640, 360, kHeadBounds, 0.0f, 0.848f);
    EXPECT_FALSE(overlapped.characters[0].runs());
    EXPECT_EQ(overlapped.characters[0].fallback,
              "84.8% of its UV texels are covered by more than one triangle (limit 2%): overlapping or mirrored UVs");
    for (const TsStep& step : overlapped.characters[0].steps) EXPECT_TRUE(step.skipped);
    EXPECT_TRUE(plan(defaultScene(), 640, 360, kHeadBounds, 0.0f, 0.5f * kMaxUvOverlapFraction).characters[0].runs());
}
