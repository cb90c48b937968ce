#pragma once
// A GL test that loads a scene (with optional --set style overrides) into a
// Renderer and reads frames back.

#include "GlTestEnvironment.h"

#include "core/Image.h"
#include "frame/Renderer.h"
#include "scene/Scene.h"

#include <memory>
#include <string>
#include <vector>

namespace dermis::test {

class RenderFixture : public GlTest {
protected:
    // sceneFile: a path, or a name in content/scenes/ ("default.json").
    void load(const std::string& sceneFile, const std::vector<std::string>& overrides = {});
    // A scene made or edited in the test.
    void use(Scene scene);
    Image render(Aov aov, int width, int height, int frames = 1);
    // The named pass's summary over the frames rendered so far, or nullptr.
    const PassSummary* pass(const std::string& name);
    std::vector<PassSummary> summary();

    std::unique_ptr<Scene> mScene;
    std::unique_ptr<Renderer> mRenderer;
    std::vector<PassSummary> mSummary;
};

// Counts texels with a non-finite colour channel.
size_t countNonFinite(const Image& image);

}  // namespace dermis::test
