#include "RenderFixture.h"

#include "TestSupport.h"

#include "scene/SceneLoader.h"

#include <cmath>
#include <filesystem>

namespace dermis::test {

void RenderFixture::load(const std::string& sceneFile, const std::vector<std::string>& overrides) {
    const std::string path = std::filesystem::exists(sceneFile) ? sceneFile : contentScene(sceneFile);
    auto scene = loadScene(path, overrides);
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    use(std::move(*scene));
}

void RenderFixture::use(Scene scene) {
    mRenderer.reset();
    mScene = std::make_unique<Scene>(std::move(scene));
    auto renderer = Renderer::create(*mScene);
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    mRenderer = std::move(*renderer);
}

Image RenderFixture::render(Aov aov, int width, int height, int frames) {
    if (!mRenderer) return {};
    for (int i = 0; i < frames; ++i) {
        const Status status = mRenderer->renderFrame({width, height, aov});
        EXPECT_TRUE(status.ok()) << status.error().message();
    }
    auto image = mRenderer->readOutput();
    EXPECT_TRUE(image.ok());
    return image.ok() ? std::move(*image) : Image{};
}

std::vector<PassSummary> RenderFixture::summary() {
    mRenderer->finishTimings();
    mSummary = mRenderer->timings().summary();
    return mSummary;
}

const PassSummary* RenderFixture::pass(const std::string& name) {
    summary();
    for (const PassSummary& s : mSummary) {
        if (s.name == name) return &s;
    }
    return nullptr;
}

size_t countNonFinite(const Image& image) {
    size_t count = 0;
    for (const glm::vec4& t : image.texels) {
        if (!std::isfinite(t.r) || !std::isfinite(t.g) || !std::isfinite(t.b)) ++count;
    }
    return count;
}

}  // namespace dermis::test
