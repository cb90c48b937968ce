// Characters off screen neither cost nor change the visible image
// (docs/crowds.md): content/scenes/crowd.json's head alone against the head
// with seven heads behind the camera, in both modes, and an off-screen head
// that moves leaves the cached shadow maps alone.
#include "RenderFixture.h"
#include "TestSupport.h"

#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace dermis;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
// One step of the 8-bit output. The heads off screen are neither drawn nor
// kept as shadow casters, and the maps are fitted to the head alone, so every
// pass the head's pixels read gets the same inputs and the image is expected
// to be the same texel for texel; one step is the bound, and the
// largest difference any change of input could round to in a pixel that did
// not otherwise change.
constexpr float kOneStep = 1.0f / 255.0f;

class Crowds : public test::RenderFixture {
protected:
    // crowd.json's first `count` characters: the head, then heads behind the camera.
    void loadCrowd(size_t count) {
        auto scene = loadScene(test::contentScene("crowd.json"));
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        scene->characters.resize(count);
        use(std::move(*scene));
    }
    Image renderIn(SssMode mode) {
        mScene->settings.mode = mode;
        return render(Aov::Final, kWidth, kHeight, 2);
    }
    bool ranThisFrame(const std::string& pass) const {
        const auto& passes = mRenderer->framePasses();
        return std::find(passes.begin(), passes.end(), pass) != passes.end();
    }
};

float maxChannelDifference(const Image& a, const Image& b) {
    EXPECT_EQ(a.texels.size(), b.texels.size());
    float largest = 0.0f;
    for (size_t i = 0; i < std::min(a.texels.size(), b.texels.size()); ++i) {
        const glm::vec3 d = glm::abs(glm::vec3(a.texels[i]) - glm::vec3(b.texels[i]));
        largest = std::max({largest, d.r, d.g, d.b});
    }
    return largest;
}

}  // namespace

// ctest: cost=35
TEST_F(Crowds, HeadsOffScreenLeaveTheVisibleHeadUnchangedInBothModes) {
    loadCrowd(1);
    const Image aloneSs = renderIn(SssMode::ScreenSpace);
    const Image aloneTs = renderIn(SssMode::TextureSpace);
    loadCrowd(8);
    const Image crowdSs = renderIn(SssMode::ScreenSpace);
    const Image crowdTs = renderIn(SssMode::TextureSpace);
    EXPECT_LE(maxChannelDifference(aloneSs, crowdSs), kOneStep + 1e-6f);
    EXPECT_LE(maxChannelDifference(aloneTs, crowdTs), kOneStep + 1e-6f);
    // The comparison sees the head: the two modes' images of it differ.
    EXPECT_GT(maxChannelDifference(aloneSs, aloneTs), 0.0f);
}

TEST_F(Crowds, AnOffScreenHeadThatMovesKeepsTheCachedShadowMaps) {
    loadCrowd(8);
    const Image before = render(Aov::Final, kWidth, kHeight, 2);
    EXPECT_FALSE(ranThisFrame("shadow:light0(dir)"));  // cached since the first frame

    mScene->characters[3].transform.translationM += glm::vec3(0.1f, 0.05f, 0.2f);
    const Image after = render(Aov::Final, kWidth, kHeight, 1);
    for (const char* pass : {"shadow:light0(dir)", "shadow:light1(spot)"}) EXPECT_FALSE(ranThisFrame(pass)) << pass;
    EXPECT_TRUE(ranThisFrame("gbuffer"));
    EXPECT_EQ(maxChannelDifference(before, after), 0.0f);

    // Moved between the head and the sun, it shades the head: the map is redrawn.
    mScene->characters[3].transform.translationM = -1.5f * glm::normalize(mScene->lights[0].direction);
    const Image shaded = render(Aov::Final, kWidth, kHeight, 1);
    EXPECT_TRUE(ranThisFrame("shadow:light0(dir)"));
    EXPECT_FALSE(ranThisFrame("shadow:light1(spot)"));
    EXPECT_GT(maxChannelDifference(before, shaded), 0.1f);
}
