// The CPU reference's images kept in the shared cache (measure/ReferenceImages.h):
// a second output directory takes the cached copy instead of computing, and a
// file the scene reads that changes (same path, new content) is computed again.
// The furnace plane lit only by an environment map that the test writes.
#include "TestSupport.h"

#include "core/Image.h"
#include "measure/ReferenceImages.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

using namespace dermis;

namespace {

size_t filesIn(const std::filesystem::path& directory) {
    size_t count = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) count += entry.is_regular_file();
    return count;
}

Image uniformMap(float radiance) {
    Image map;
    map.width = 32;
    map.height = 16;
    map.colourSpace = ColourSpace::Linear;
    map.texels.assign(size_t(map.width) * size_t(map.height), glm::vec4(radiance, radiance, radiance, 1.0f));
    return map;
}

}  // namespace

TEST(ReferenceCache, AnotherDirectoryReusesTheImageAndAChangedFileIsComputedAgain) {
    test::TempDir dir;
    const std::filesystem::path cache = dir.file("cache");
    ::setenv("DERMIS_CACHE_DIR", cache.c_str(), 1);
    const std::string mapPath = dir.file("sky.exr");
    ASSERT_TRUE(saveImage(mapPath, uniformMap(0.5f)).ok());
    auto scene = loadScene(test::contentScene("furnace.json"),
                           {"lights=[]", "environment={\"source\":\"" + mapPath + "\"}"});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    measure::ReferenceSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.density = 2.0f;

    auto first = measure::ReferenceImages(dir.file("a"), settings).full(*scene);
    ASSERT_TRUE(first.ok()) << first.error().message();
    const std::filesystem::path shared = cache / "reference";
    ASSERT_EQ(filesIn(shared), 2u) << "the image and its identity";

    // The shared copy, marked (halved), is what another directory gets: nothing is computed.
    std::filesystem::path copy;
    for (const auto& entry : std::filesystem::directory_iterator(shared)) {
        if (entry.path().extension() == ".exr") copy = entry.path();
    }
    Image marked = *first;
    for (glm::vec4& texel : marked.texels) texel = glm::vec4(glm::vec3(texel) * 0.5f, texel.a);
    ASSERT_TRUE(saveImage(copy.string(), marked).ok());
    auto second = measure::ReferenceImages(dir.file("b"), settings).full(*scene);
    ASSERT_TRUE(second.ok()) << second.error().message();
    size_t lit = 0;
    for (size_t i = 0; i < first->texels.size(); ++i) {
        lit += first->texels[i].r > 0.01f;
        ASSERT_EQ(second->texels[i], marked.texels[i]) << "texel " << i;
    }
    ASSERT_GT(lit, first->texels.size() / 2) << "the sky lights the plane";
    EXPECT_EQ(filesIn(shared), 2u);

    // The map's file changes under the same path: a new key, computed, and the plane's
    // light scales with the map (the same rays, radiance x 1.2).
    ASSERT_TRUE(saveImage(mapPath, uniformMap(0.6f)).ok());
    auto third = measure::ReferenceImages(dir.file("c"), settings).full(*scene);
    ASSERT_TRUE(third.ok()) << third.error().message();
    EXPECT_EQ(filesIn(shared), 4u);
    for (size_t i = 0; i < first->texels.size(); ++i) {
        if (first->texels[i].r > 0.01f) ASSERT_NEAR(third->texels[i].r / first->texels[i].r, 1.2f, 1e-4f) << i;
    }
    ::unsetenv("DERMIS_CACHE_DIR");
}
