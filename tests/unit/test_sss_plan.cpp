// What the SSS chain decides to run, on the CPU alone.
#include "plan/SssPlan.h"
#include "sss/DiffusionProfile.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;

namespace {

Scene headScene(const std::string& profile = "skin") {
    Scene scene;
    Character head;
    head.name = "head";
    head.mesh.procedural = "head";
    head.material.profile = profile;
    scene.characters.push_back(head);
    return scene;
}

const Bounds kHeadBounds{glm::vec3(-0.1f, -0.19f, -0.12f), glm::vec3(0.1f, 0.13f, 0.12f)};

ViewParams viewFrom(float distanceM, int width = 640, int height = 360) {
    ViewParams view;
    view.viewFromWorld = glm::lookAt(glm::vec3(0, 0, distanceM), glm::vec3(0), glm::vec3(0, 1, 0));
    view.clipFromView = glm::perspective(glm::radians(35.0f), float(width) / float(height), 0.05f, 100.0f);
    view.nearM = 0.05f;
    view.widthPx = width;
    view.heightPx = height;
    return view;
}

int executedSteps(const SssSlotPlan& slot) {
    int n = 0;
    for (const SssGaussianStep& s : slot.steps) n += s.skipped ? 0 : 1;
    return n;
}

glm::vec3 totalWeight(const SssSlotPlan& slot) {
    glm::vec3 sum = slot.initWeight;
    for (const SssGaussianStep& s : slot.steps) {
        if (!s.skipped) sum += s.weight;
    }
    return sum;
}

}  // namespace

TEST(SssPlan, NearHeadSkipsOnlyTheSubPixelIdentityGaussian) {
    auto plan = planSss(headScene(), {kHeadBounds}, viewFrom(0.45f));
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    ASSERT_EQ(plan->slots.size(), 1u);
    const SssSlotPlan& slot = plan->slots[0];
    EXPECT_TRUE(slot.visible);
    EXPECT_EQ(slot.slot, 1);
    EXPECT_EQ(plan->slotOf(0, 0), 1);
    ASSERT_EQ(slot.steps.size(), 6u);
    EXPECT_TRUE(slot.steps[0].skipped);  // 0.0064 mm^2: the identity at this distance
    EXPECT_FALSE(slot.steps[5].skipped);
    EXPECT_GT(slot.scissor.z, 0);
    EXPECT_GT(slot.scissor.w, 0);
}

TEST(SssPlan, FarHeadRunsFewerBlursThanNear) {
    auto near = planSss(headScene(), {kHeadBounds}, viewFrom(0.45f));
    auto far = planSss(headScene(), {kHeadBounds}, viewFrom(6.0f));
    ASSERT_TRUE(near.ok() && far.ok());
    EXPECT_LT(executedSteps(far->slots[0]), executedSteps(near->slots[0]));
}

// Whether a slot is blurred on screen decides which characters the thin-edge
// back-depth pass draws (passes/ThinEdgePasses.cpp). The widest Gaussian's
// width in pixels is worked out here from the view, independently of the
// plan: 360 px over the 35-degree field, at the head's nearest depth
// (distance - 0.12 m). At 4 m it is 0.21 px, under the 0.5 px minimum, so the
// chain is the identity and nothing reads the fill; at 1.2 m 0.76 px.
TEST(SssPlan, ASlotBlursOnScreenUnlessNoGaussianReachesMinWidthOrItScattersInTheLightingPass) {
    const double widestSigmaMm = std::sqrt(double(skinProfile().gaussians().back().varianceMm2));
    const double pixelsPerMetreAtUnitDepth = 360.0 / (2.0 * std::tan(glm::radians(35.0) / 2.0));
    const auto widestPx = [&](double distanceM) { return widestSigmaMm * pixelsPerMetreAtUnitDepth / (distanceM - 0.12) * 1e-3; };
    ASSERT_LT(widestPx(4.0), 0.5);
    ASSERT_GT(widestPx(1.2), 0.5);
    const float minWidthPx = Scene().settings.sss.minWidthPx;
    ASSERT_EQ(minWidthPx, 0.5f);

    auto far = planSss(headScene(), {kHeadBounds}, viewFrom(4.0f));
    auto middle = planSss(headScene(), {kHeadBounds}, viewFrom(1.2f));
    ASSERT_TRUE(far.ok() && middle.ok());
    EXPECT_FALSE(blursOnScreen(far->slots[0]));
    EXPECT_TRUE(blursOnScreen(middle->slots[0]));

    for (SssTechnique technique : {SssTechnique::Disk, SssTechnique::Separable, SssTechnique::Preintegrated}) {
        Scene scene = headScene();
        scene.settings.sss.technique = technique;
        auto plan = planSss(scene, {kHeadBounds}, viewFrom(0.45f));
        ASSERT_TRUE(plan.ok());
        EXPECT_EQ(blursOnScreen(plan->slots[0]), technique != SssTechnique::Preintegrated) << int(technique);
    }
    // Behind the camera: nothing blurs.
    const Bounds behindCamera{glm::vec3(-0.1f, -0.1f, 1.0f), glm::vec3(0.1f, 0.1f, 1.2f)};
    auto behind = planSss(headScene(), {behindCamera}, viewFrom(0.45f));
    ASSERT_TRUE(behind.ok());
    EXPECT_FALSE(blursOnScreen(behind->slots[0]));
}

// "sss init" only copies the irradiance times the slot's initWeight; when
// nothing blurs and that weight is 1 the copy is the irradiance itself, and
// the pass is skipped (SssPlan::chainIsIdentity). At 4 m every skin Gaussian
// is under min_width_px (the test above works it out from the view); at 1.2 m
// one is not. Profiles are normalised when made, so a weight other than 1 is
// planted here to show that the weight, not the steps alone, decides.
TEST(SssPlan, TheChainIsTheIrradianceOnlyWhenNothingBlursAndTheWeightIsWhole) {
    auto far = planSss(headScene(), {kHeadBounds}, viewFrom(4.0f));
    auto middle = planSss(headScene(), {kHeadBounds}, viewFrom(1.2f));
    ASSERT_TRUE(far.ok() && middle.ok());
    EXPECT_TRUE(far->chainIsIdentity());
    EXPECT_FALSE(middle->chainIsIdentity());

    glm::dvec3 sum(0.0);  // the skin profile's weights, summed here: the whole irradiance
    for (const ProfileGaussian& g : skinProfile().gaussians()) sum += glm::dvec3(g.weight);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sum[c], 1.0, 1e-6) << c;

    SssPlan darker = *far;
    darker.slots[0].initWeight = glm::vec3(0.8f);
    EXPECT_FALSE(darker.chainIsIdentity());

    // Off screen: no slot is visible, and nothing is judged.
    const Bounds behindCamera{glm::vec3(-0.1f, -0.1f, 1.0f), glm::vec3(0.1f, 0.1f, 1.2f)};
    auto behind = planSss(headScene(), {behindCamera}, viewFrom(0.45f));
    ASSERT_TRUE(behind.ok());
    EXPECT_FALSE(behind->chainIsIdentity());
}

TEST(SssPlan, SkippedGaussiansKeepTheirEnergyInTheIdentityTerm) {
    for (float distance : {0.3f, 1.0f, 3.0f, 20.0f}) {
        auto plan = planSss(headScene(), {kHeadBounds}, viewFrom(distance));
        ASSERT_TRUE(plan.ok());
        const glm::vec3 total = totalWeight(plan->slots[0]);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], 1.0f, 1e-5f) << "at " << distance << " m";
    }
}

TEST(SssPlan, ExecutedStepsBlurTheIrradianceByExactlyTheWidestVariance) {
    // The chain's variance after the last step is the sum of the executed steps' variances; it
    // must be the widest Gaussian's v (times width_scale^2) whether or not narrow ones were
    // skipped: a skipped Gaussian leaves the chain unblurred, so the first step that runs blurs
    // by its whole v_i (v_i - v_(i-1) there would leave that Gaussian and all wider ones
    // narrower by v_(i-1): 0.0064 mm^2, 13% of Gaussian 1's variance).
    const auto& skin = skinProfile().gaussians();
    for (float distance : {0.02f, 0.45f, 3.0f}) {
        for (float widthScale : {1.0f, 1.05f}) {
            Scene scene = headScene();
            scene.settings.sss.widthScale = widthScale;
            auto plan = planSss(scene, {kHeadBounds}, viewFrom(distance));
            ASSERT_TRUE(plan.ok());
            const SssSlotPlan& slot = plan->slots[0];
            double total = 0.0;
            int readers = 0;
            bool seenExecuted = false;
            for (const SssGaussianStep& step : slot.steps) {
                if (step.skipped) continue;
                total += step.stepVarianceMm2;
                readers += step.readsIrradiance ? 1 : 0;
                EXPECT_EQ(step.readsIrradiance, !seenExecuted) << "only the first step that runs reads the irradiance";
                seenExecuted = true;
            }
            if (!seenExecuted) continue;
            EXPECT_EQ(readers, 1);
            EXPECT_NEAR(total / (double(skin.back().varianceMm2) * widthScale * widthScale), 1.0, 1e-5)
                << "at " << distance << " m, width scale " << widthScale;
        }
    }
}

TEST(SssPlan, FewerGaussiansFoldTheWidestIntoTheLastKept) {
    Scene scene = headScene();
    scene.settings.sss.gaussians = 3;
    auto plan = planSss(scene, {kHeadBounds}, viewFrom(0.45f));
    ASSERT_TRUE(plan.ok());
    ASSERT_EQ(plan->slots[0].steps.size(), 3u);
    const glm::vec3 total = totalWeight(plan->slots[0]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(total[c], 1.0f, 1e-5f);
}

TEST(SssPlan, OffScreenAndOpaqueCharactersRunNothing) {
    const Bounds behindCamera{glm::vec3(-0.1f, -0.1f, 1.0f), glm::vec3(0.1f, 0.1f, 1.2f)};
    auto plan = planSss(headScene(), {behindCamera}, viewFrom(0.45f));
    ASSERT_TRUE(plan.ok());
    EXPECT_FALSE(plan->anyVisible());
    EXPECT_EQ(executedSteps(plan->slots[0]), 0);

    auto opaque = planSss(headScene("none"), {kHeadBounds}, viewFrom(0.45f));
    ASSERT_TRUE(opaque.ok());
    EXPECT_TRUE(opaque->slots.empty());
    EXPECT_EQ(opaque->slotOf(0, 0), 0);
}

TEST(SssPlan, CharactersSharingAProfileShareASlot) {
    Scene scene = headScene();
    scene.characters.push_back(scene.characters[0]);
    Character stone = scene.characters[0];
    stone.material.profile = "marble";
    scene.characters.push_back(stone);
    auto plan = planSss(scene, {kHeadBounds, kHeadBounds, kHeadBounds}, viewFrom(0.45f));
    ASSERT_TRUE(plan.ok());
    EXPECT_EQ(plan->slots.size(), 2u);
    EXPECT_EQ(plan->slotsOfCharacter, (std::vector<std::vector<int>>{{1}, {1}, {2}}));
}

TEST(SssPlan, UnknownProfileIsAnError) {
    auto plan = planSss(headScene("jelly"), {kHeadBounds}, viewFrom(0.45f));
    ASSERT_FALSE(plan.ok());
    EXPECT_NE(plan.error().message().find("jelly"), std::string::npos);
    EXPECT_NE(plan.error().message().find("head"), std::string::npos);
}

TEST(SssPlan, BackLightIsOnTheFarSideFromTheCamera) {
    Light back;
    back.type = LightType::Directional;
    back.direction = glm::vec3(0, 0, 1);  // travels towards the camera at +z: comes from behind
    Light key;
    key.type = LightType::Directional;
    key.direction = glm::vec3(0, 0, -1);
    const glm::vec3 camera(0, 0, 0.45f);
    EXPECT_TRUE(isBackLight(back, kHeadBounds, camera));
    EXPECT_FALSE(isBackLight(key, kHeadBounds, camera));
}
