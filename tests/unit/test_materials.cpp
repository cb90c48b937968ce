// Materials per primitive without GL (docs/materials.md): the glTF loader
// keeps every material, submesh and COLOR_0 of the multi-material strip
// (tests/support/TestContent.h); the scene's `materials` and `profiles` are
// read or refused with one line naming the key; both SSS planners give each
// (profile, width scale) its own slot or surface.
#include "TestContent.h"
#include "TestSupport.h"

#include "import/GltfLoader.h"
#include "plan/SceneGeometry.h"
#include "render/SceneLoading.h"
#include "plan/SssPlan.h"
#include "plan/TsPlan.h"
#include "scene/SceneLoader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

using namespace dermis;
using Strip = test::MultiMaterialStrip;

namespace {

class MaterialsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(test::writeMultiMaterialStrip(mDir.file("multi_material.gltf")));
    }
    std::string sceneWith(const std::string& characterMembers, const std::string& rootMembers = "") const {
        const std::string json = R"({)" + rootMembers + R"("characters": [{"name": "strip", "mesh": {"gltf": "multi_material.gltf"})" +
                                 characterMembers + "}]}";
        test::writeTextFile(mDir.file("scene.json"), json);
        return mDir.file("scene.json");
    }
    test::TempDir mDir;
};

TEST_F(MaterialsTest, LoaderKeepsEveryMaterialSubmeshAndVertexColour) {
    auto model = loadGltf(mDir.file("multi_material.gltf"));
    ASSERT_TRUE(model) << model.error().message();
    ASSERT_EQ(model->materials.size(), size_t(Strip::kPrimitives));
    ASSERT_EQ(model->submeshes.size(), size_t(Strip::kPrimitives));
    ASSERT_EQ(model->colours.size(), model->mesh.vertices.size());
    uint32_t nextIndex = 0;
    for (int p = 0; p < Strip::kPrimitives; ++p) {
        const ModelMaterial& material = model->materials[size_t(p)];
        EXPECT_EQ(material.name, Strip::kNames[p]);
        EXPECT_EQ(material.baseColourFactor, Strip::kFactors[p]);
        EXPECT_TRUE(material.albedoMap.empty());
        const Submesh& submesh = model->submeshes[size_t(p)];
        EXPECT_EQ(submesh.material, p);
        EXPECT_EQ(submesh.firstIndex, nextIndex);
        nextIndex += submesh.indexCount;
        // Every vertex of the primitive has its half's colour: float, unorm8 (exact in k/255) and unorm16.
        const double bound = p == 0 ? 0.0 : p == 1 ? 1e-6 : 1.0 / 65535.0;
        int checked = 0;
        for (uint32_t i = submesh.firstIndex; i < submesh.firstIndex + submesh.indexCount; ++i) {
            const uint32_t v = model->mesh.indices[i];
            const float stepX = Strip::leftXM(p) + 0.5f * Strip::kWidthM;
            const glm::vec3 expected = Strip::kColours[p][model->mesh.vertices[v].position.x < stepX ? 0 : 1];
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(model->colours[v][c], expected[c], bound) << "primitive " << p;
            EXPECT_EQ(model->colours[v].a, 1.0f);
            ++checked;
        }
        EXPECT_GT(checked, 0);
    }
    EXPECT_EQ(nextIndex, model->mesh.indices.size());
}

TEST_F(MaterialsTest, FileWithoutColoursHasNoneAndOneMaterial) {
    const std::string file = mDir.file("cylinder.gltf");
    ASSERT_TRUE(test::writeBendingCylinder(file));
    auto model = loadGltf(file);
    ASSERT_TRUE(model) << model.error().message();
    EXPECT_TRUE(model->colours.empty());
    ASSERT_EQ(model->materials.size(), 1u);
    EXPECT_EQ(model->materials[0].name, "");
    ASSERT_EQ(model->drawRanges().size(), 1u);
    EXPECT_EQ(model->drawRanges()[0].indexCount, model->mesh.indices.size());
}

TEST_F(MaterialsTest, MaterialOverridesStartFromTheCharactersMaterial) {
    auto scene = loadScene(sceneWith(
        R"(, "material": {"albedo": [1, 1, 1], "rho_s": 0.3},
             "materials": {"Cloth": {"profile": "none", "roughness": 0.6},
                           "Skin": {"width_scale": 1.2, "specular_map": "spec.png", "roughness_map": "rough.png"}})"));
    ASSERT_TRUE(scene) << scene.error().message();
    const Character& c = scene->characters[0];
    const Material& cloth = characterMaterial(c, "Cloth");
    EXPECT_EQ(cloth.profile, "none");
    EXPECT_EQ(cloth.roughness, 0.6f);
    EXPECT_EQ(cloth.rhoS, 0.3f);  // the character's
    EXPECT_EQ(cloth.albedo, glm::vec3(1.0f));
    const Material& skin = characterMaterial(c, "Skin");
    EXPECT_EQ(skin.widthScale, 1.2f);
    EXPECT_EQ(skin.specularMap, mDir.file("spec.png"));
    EXPECT_EQ(skin.roughnessMap, mDir.file("rough.png"));
    EXPECT_EQ(&characterMaterial(c, "Wax"), &c.material);
}

// One line each, naming the file and the key.
TEST_F(MaterialsTest, BadMaterialsAndProfilesAreRefusedWithTheirKey) {
    const std::string gaussian = R"({"variance_mm2": 1, "weights": [1, 1, 1]})";
    struct Case {
        std::string characterMembers, rootMembers, pointer, words;
    };
    const Case cases[] = {
        {R"(, "materials": {"Skin": {"width_scale": 0}})", "", "/characters/0/materials/Skin/width_scale", "must be in (0, 10000]"},
        {R"(, "materials": {"Skin": {"profile": "jelly"}})", "", "/characters/0/materials/Skin/profile",
         "unknown diffusion profile"},
        {R"(, "materials": {"Skin": {"shine": 1}})", "", "/characters/0/materials/Skin/shine", "unknown key"},
        {R"(, "materials": [])", "", "/characters/0/materials", "must be an object"},
        {"", R"("profiles": {"skin": {"gaussians": [)" + gaussian + "]}}, ", "/profiles/skin",
         "may not be named \"skin\""},
        {"", R"("profiles": {"none": {"gaussians": [)" + gaussian + "]}}, ", "/profiles/none", "may not be named"},
        {"", R"("profiles": {"p": {"gaussians": []}}, )", "/profiles/p/gaussians", "give 1 to 8 Gaussians"},
        {"", R"("profiles": {"p": {"gaussians": [)" + gaussian + "," + gaussian + "]}}, ",
         "/profiles/p/gaussians/1/variance_mm2", "must increase strictly"},
        {"", R"("profiles": {"p": {"gaussians": [{"variance_mm2": 0, "weights": [1, 1, 1]}]}}, )",
         "/profiles/p/gaussians/0/variance_mm2", "> 0"},
        {"", R"("profiles": {"p": {"gaussians": [{"variance_mm2": 1, "weights": [1, -0.5, 1]}]}}, )",
         "/profiles/p/gaussians/0/weights/1", "must be in [0, 1]"},
        {"", R"("profiles": {"p": {"gaussians": [{"variance_mm2": 1, "weights": [1, 0.99, 1]}]}}, )",
         "/profiles/p/gaussians", "the green weights sum to 0.99;"},
        {"", R"("profiles": {"p": {"gaussians": [{"variance_mm2": 1}]}}, )", "/profiles/p/gaussians/0",
         "needs \"variance_mm2\" and \"weights\""},
        {"", R"("profiles": {"p": {"gaussians": [)" + std::string(9, ' ') + gaussian +
                 [&] { std::string more; for (int i = 0; i < 8; ++i) more += "," + gaussian; return more; }() + "]}}, ",
         "/profiles/p/gaussians", "too many Gaussians"},
    };
    for (const Case& c : cases) {
        auto scene = loadScene(sceneWith(c.characterMembers, c.rootMembers));
        ASSERT_FALSE(scene.ok()) << c.pointer;
        const std::string what = scene.error().message();
        EXPECT_NE(what.find(mDir.file("scene.json")), std::string::npos) << what;
        EXPECT_NE(what.find(c.pointer + ":"), std::string::npos) << what;
        EXPECT_NE(what.find(c.words), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST_F(MaterialsTest, UnknownGltfMaterialNameListsTheFilesNames) {
    auto scene = loadScene(sceneWith(R"(, "materials": {"Face": {"profile": "none"}})"));
    ASSERT_TRUE(scene) << scene.error().message();
    auto models = loadSceneModels(*scene);
    ASSERT_FALSE(models.ok());
    const std::string what = models.error().message();
    EXPECT_NE(what.find("/characters/0/materials/Face: 'Face' is not a material of"), std::string::npos) << what;
    EXPECT_NE(what.find("(its materials: 'Skin', 'Cloth', 'Wax'; or #0 to #2 by index)"), std::string::npos) << what;
}

TEST_F(MaterialsTest, UserProfileIsFoundAndRoundTrips) {
    auto scene = loadScene(sceneWith(R"(, "material": {"profile": "thin"})",
                                     R"("profiles": {"thin": {"gaussians": [{"variance_mm2": 0.01, "weights": [0.5, 0.5, 0.5]},
                                                                           {"variance_mm2": 0.1, "weights": [0.5, 0.5, 0.5]}]}}, )"));
    ASSERT_TRUE(scene) << scene.error().message();
    auto profile = findSceneProfile(*scene, "thin");
    ASSERT_TRUE(profile.ok());
    ASSERT_EQ((*profile)->size(), 2u);
    EXPECT_EQ((*profile)->gaussians()[1].varianceMm2, 0.1f);
    EXPECT_EQ((*profile)->gaussians()[1].weight, glm::vec3(0.5f));
    auto reread = parseScene(sceneToJson(*scene), scene->path);
    ASSERT_TRUE(reread) << reread.error().message();
    ASSERT_EQ(reread->profiles.size(), 1u);
    EXPECT_EQ(reread->profiles[0].gaussians()[0].varianceMm2, 0.01f);
    EXPECT_EQ(findSceneProfile(*scene, "jelly").error().what,
              "unknown diffusion profile \"jelly\" (known: skin, marble, thin)");
}

ViewParams frontView() {
    ViewParams view;
    view.viewFromWorld = glm::lookAt(glm::vec3(0, 0, 0.5f), glm::vec3(0), glm::vec3(0, 1, 0));
    view.clipFromView = glm::perspective(glm::radians(30.0f), 640.0f / 360.0f, 0.05f, 10.0f);
    view.widthPx = 640;
    view.heightPx = 360;
    return view;
}

const Bounds kBounds{glm::vec3(-0.03f, -0.02f, -0.001f), glm::vec3(0.03f, 0.02f, 0.001f)};

Scene planScene() {
    auto scene = parseScene(R"({"characters": [
        {"name": "a", "mesh": {"procedural": "plane"}, "material": {"profile": "skin"},
         "materials": {"Cloth": {"profile": "none"}, "Wide": {"width_scale": 2}, "Wax": {"profile": "marble"}}},
        {"name": "b", "mesh": {"procedural": "plane"}}]})",
                            "x.json");
    EXPECT_TRUE(scene) << scene.error().message();
    return *scene;
}

TEST(MaterialPlans, ScreenSpaceSlotsPerProfileAndWidthScale) {
    const Scene scene = planScene();
    const std::vector<std::vector<SubmeshMaterial>> names = {{{"Skin"}, {"Cloth"}, {"Wide"}, {"Wax"}, {"Skin"}}, {}};
    auto plan = planSss(scene, {kBounds, kBounds}, frontView(), names);
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    // skin at width 1 (slot 1, shared with character b), skin at width 2, marble; the cloth opaque.
    EXPECT_EQ(plan->slotsOfCharacter, (std::vector<std::vector<int>>{{1, 0, 2, 3, 1}, {1}}));
    ASSERT_EQ(plan->slots.size(), 3u);
    EXPECT_EQ(plan->slots[1].widthScale, 2.0f);
    // Width scale 2 blurs each step by 4x the variance.
    ASSERT_FALSE(plan->slots[1].steps.empty());
    EXPECT_FLOAT_EQ(plan->slots[1].steps.back().stepVarianceMm2, 4.0f * plan->slots[0].steps.back().stepVarianceMm2);
    EXPECT_EQ(plan->slots[2].profile, &marbleProfile());
}

TEST(MaterialPlans, TextureSpaceSurfacePerProfile) {
    const Scene scene = planScene();
    std::vector<TsCharacterInput> inputs(2, TsCharacterInput{kBounds, 40.0f, 40.0f});
    inputs[0].submeshMaterials = {{"Skin"}, {"Cloth"}, {"Wide"}, {"Wax"}, {"Skin"}};
    auto plan = planTextureSpace(scene, inputs, frontView(), LightSetup{});
    ASSERT_TRUE(plan.ok()) << plan.error().message();
    ASSERT_EQ(plan->characters.size(), 4u);
    EXPECT_EQ(plan->characters[0].submeshes, (std::vector<size_t>{0, 4}));
    EXPECT_EQ(plan->characters[0].label, "a skin 0");
    EXPECT_EQ(plan->characters[1].submeshes, (std::vector<size_t>{2}));
    EXPECT_EQ(plan->characters[1].widthScale, 2.0f);
    EXPECT_EQ(plan->characters[2].submeshes, (std::vector<size_t>{3}));
    EXPECT_EQ(plan->characters[2].profile, &marbleProfile());
    EXPECT_EQ(plan->characters[3].label, "b");
    EXPECT_EQ(plan->characters[3].submeshes, (std::vector<size_t>{0}));
}

}  // namespace
