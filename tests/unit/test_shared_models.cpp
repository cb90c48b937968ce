// Characters that repeat a model share it (render/SceneLoading.h,
// loadSharedSceneModels): content/scenes/crowd8_mixed.json's eight heads load
// one model; a head whose material differs loads its own; the names, places
// and motions of characters do not count.
#include "TestSupport.h"

#include "render/SceneLoading.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <set>

namespace dermis {
namespace {

size_t distinctModels(const SceneModels& models) {
    std::set<const Model*> distinct;
    for (const auto& model : models) distinct.insert(model.get());
    return distinct.size();
}

TEST(SharedModels, RepeatedHeadsLoadOneModel) {
    auto scene = loadScene(test::contentScene("crowd8_mixed.json"));
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto models = loadSharedSceneModels(*scene);
    ASSERT_TRUE(models.ok()) << models.error().message();
    ASSERT_EQ(models->size(), 8u);
    EXPECT_EQ(distinctModels(*models), 1u);
}

TEST(SharedModels, AnotherMaterialLoadsItsOwn) {
    auto scene = loadScene(test::contentScene("crowd8_mixed.json"),
                           {"characters.3.material.roughness=0.5", "characters.5.material.albedo=[0.9,0.8,0.7]",
                            "characters.6.animation.speed=2"});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto models = loadSharedSceneModels(*scene);
    ASSERT_TRUE(models.ok()) << models.error().message();
    EXPECT_EQ(distinctModels(*models), 3u);
    EXPECT_NE((*models)[3].get(), (*models)[0].get());
    EXPECT_NE((*models)[5].get(), (*models)[0].get());
    EXPECT_EQ((*models)[6].get(), (*models)[0].get()) << "how a character moves is not its model";
    // Copies for code that changes them: one per character, equal to the shared one.
    auto copies = loadSceneModels(*scene);
    ASSERT_TRUE(copies.ok());
    ASSERT_EQ(copies->size(), 8u);
    EXPECT_EQ((*copies)[7].mesh.indices, (*models)[7]->mesh.indices);
}

}  // namespace
}  // namespace dermis
