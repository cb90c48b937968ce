// The CPU reference follows the same masks as the engine (docs/materials.md,
// "Skin only where there is skin"): on the multi-material strip of
// tests/support/TestContent.h under one unshadowed unit sun from straight
// above, with mix = 1 and no energy conservation, a point's local diffuse is
// exactly its albedo (E = 1). So
//   - cloth, opaque by its name, is its albedo to float rounding (closed form);
//   - skin near its albedo step is blurred (differs from its albedo);
//   - skin with scatter 0.5 is the halfway mix of its own light and its blur.
#include "TestContent.h"
#include "TestSupport.h"

#include "import/ModelLoader.h"
#include "reference/ReferenceRenderer.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace dermis;
using Strip = test::MultiMaterialStrip;

namespace {

std::vector<glm::vec4> diffuseAt(const test::TempDir& dir, const std::string& materials,
                                 const std::vector<glm::vec2>& pointsM) {
    std::string error;
    EXPECT_TRUE(test::writeMultiMaterialStrip(dir.file("strip.gltf"), &error)) << error;
    test::writeTextFile(dir.file("strip.json"), R"({
      "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1, "shadow": false}],
      "characters": [{"name": "strip", "mesh": {"gltf": "strip.gltf"},
                      "material": {"albedo": [1, 1, 1], "rho_s": 0, "profile": "skin"}, "materials": )" + materials + R"(}],
      "settings": {"ambient": [0, 0, 0], "energy_conservation": false, "sss": {"mix": 1}}})");
    auto scene = loadScene(dir.file("strip.json"));
    EXPECT_TRUE(scene) << scene.error().message();
    auto models = loadSceneModels(*scene);
    EXPECT_TRUE(models) << models.error().message();
    reference::ReferenceOptions options;
    options.threads = 2;
    auto renderer = reference::ReferenceRenderer::create(*scene, std::move(*models), options);
    EXPECT_TRUE(renderer) << renderer.error().message();
    std::vector<raytrace::Ray> rays;
    for (const glm::vec2& p : pointsM) rays.push_back({glm::vec3(p.x, 0.01f, p.y), glm::vec3(0.0f, -1.0f, 0.0f)});
    return renderer->diffuseAlongRays(rays, 0.0f, 0.02f);
}

// Points of primitive `p` at `offsetM` from its albedo step, along z = 0 and z = 5 mm.
std::vector<glm::vec2> nearStep(int p, const std::vector<float>& offsetsM) {
    const float step = Strip::leftXM(p) + 0.5f * Strip::kWidthM;
    std::vector<glm::vec2> points;
    for (float z : {0.0f, 0.005f})
        for (float offset : offsetsM) points.push_back({step + offset, z});
    return points;
}

glm::vec3 albedoOf(int p, float offsetM) {
    return glm::vec3(Strip::kFactors[p]) * Strip::kColours[p][offsetM < 0.0f ? 0 : 1];
}

const std::vector<float> kOffsetsM = {-0.004f, -0.001f, -0.0003f, 0.0003f, 0.001f, 0.004f};

}  // namespace

TEST(ReferenceScatterShare, ClothOpaqueByItsNameIsItsAlbedoAndSkinBlurs) {
    test::TempDir dir;
    std::vector<glm::vec2> points = nearStep(1, kOffsetsM);
    const std::vector<glm::vec2> skin = nearStep(0, kOffsetsM);
    points.insert(points.end(), skin.begin(), skin.end());
    const std::vector<glm::vec4> values = diffuseAt(dir, R"({"Wax": {"profile": "marble"}})", points);
    ASSERT_EQ(values.size(), points.size());
    double clothWorst = 0.0, skinSmallest = 1e9;
    const size_t half = points.size() / 2;
    for (size_t i = 0; i < points.size(); ++i) {
        const float offset = kOffsetsM[i % kOffsetsM.size()];
        const glm::vec3 d = glm::abs(glm::vec3(values[i]) - albedoOf(i < half ? 1 : 0, offset));
        const double worst = std::max({d.r, d.g, d.b});
        if (i < half) {
            clothWorst = std::max(clothWorst, worst);
        } else if (std::abs(offset) < 0.0005f) {
            skinSmallest = std::min(skinSmallest, worst);
        }
    }
    std::printf("reference: cloth off its albedo by at most %.2e; skin within 0.3 mm of its step by at least %.3f\n",
                clothWorst, skinSmallest);
    // Float rounding of E = N.L = 1 and the albedo product.
    EXPECT_LT(clothWorst, 1e-5);
    EXPECT_GT(skinSmallest, 0.05);
}

TEST(ReferenceScatterShare, HalfTheShareIsTheHalfwayMix) {
    test::TempDir dir;
    const std::vector<glm::vec2> points = nearStep(0, kOffsetsM);
    const std::vector<glm::vec4> full = diffuseAt(dir, R"({"Skin": {"scatter": 1}})", points);
    const std::vector<glm::vec4> half = diffuseAt(dir, R"({"Skin": {"scatter": 0.5}})", points);
    ASSERT_EQ(full.size(), points.size());
    ASSERT_EQ(half.size(), points.size());
    double worst = 0.0, largestBlur = 0.0;
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 local = albedoOf(0, kOffsetsM[i % kOffsetsM.size()]);
        const glm::vec3 expected = 0.5f * local + 0.5f * glm::vec3(full[i]);
        const glm::vec3 miss = glm::abs(glm::vec3(half[i]) - expected);
        worst = std::max({worst, double(miss.r), double(miss.g), double(miss.b)});
        const glm::vec3 blur = glm::abs(glm::vec3(full[i]) - local);
        largestBlur = std::max({largestBlur, double(blur.r), double(blur.g), double(blur.b)});
    }
    std::printf("reference: s = 0.5 off the halfway mix by at most %.2e (the blur moves up to %.3f)\n", worst, largestBlur);
    // The same quadrature in both renders: only float rounding separates them.
    EXPECT_GT(largestBlur, 0.05);
    EXPECT_LT(worst, 1e-5);
}
