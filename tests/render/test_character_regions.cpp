// The lighting pass and the composite clear their targets to the
// background's value and draw only the rectangles the visible characters'
// bounds cover (passes/FullscreenPass.h, characterRegions). Every pixel a
// character covers (object AOV) must still be lit and composited, and every
// other pixel must hold the background: in the budget crowd, whose near head
// is cut by the frame's left edge and whose far heads are a few pixels, in
// both modes. Leaving one visible character's rectangle out of
// characterRegions fails it with 2,841 unlit pixels.
#include "RenderFixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

using namespace dermis;
using namespace dermis::test;

namespace {

class CharacterRegions : public RenderFixture {};

TEST_F(CharacterRegions, EveryCharacterPixelIsLitAndEveryOtherIsTheBackground) {
    constexpr int kWidth = 160;
    constexpr int kHeight = 90;
    for (const char* mode : {"ss", "ts"}) {
        load("crowd8_mixed.json", {std::string("mode=") + mode});
        const Image ids = render(Aov::Object, kWidth, kHeight);
        const Image irradiance = render(Aov::Irradiance, kWidth, kHeight);
        const Image radiance = render(Aov::Radiance, kWidth, kHeight);
        ASSERT_EQ(ids.texels.size(), radiance.texels.size());
        const glm::vec3 background = mScene->background.colour;
        int characterPixels = 0;
        int unlit = 0;
        int notComposited = 0;
        int wrongBackground = 0;
        for (size_t i = 0; i < ids.texels.size(); ++i) {
            const glm::vec3 lit(irradiance.texels[i]);
            const glm::vec3 colour(radiance.texels[i]);
            if (std::lround(ids.texels[i].r) >= 1) {
                ++characterPixels;
                // The scene's ambient (0.06) reaches every pixel of a character: none is 0
                // unless its pass left it out (the cleared value).
                if (std::string(mode) == "ss" && glm::dot(lit, glm::vec3(1.0f)) <= 0.0f) ++unlit;
                if (glm::dot(colour, glm::vec3(1.0f)) <= 0.0f) ++notComposited;
            } else {
                // Half-float targets: the background colour to 1e-3.
                if (glm::length(colour - background) > 1e-3f) ++wrongBackground;
            }
        }
        ASSERT_GT(characterPixels, 1000) << mode;
        EXPECT_EQ(unlit, 0) << mode;
        EXPECT_EQ(notComposited, 0) << mode;
        EXPECT_EQ(wrongBackground, 0) << mode;
    }
}

}  // namespace
