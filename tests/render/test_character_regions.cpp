// The lighting pass and the composite clear their targets to the
// background's value and draw only the rectangles the visible characters'
// bounds cover (passes/FullscreenPass.h, characterRegions). Every pixel a
// character covers (object AOV) must still be lit and composited, and every
// other pixel must hold the background: in the budget crowd, whose near head
// is cut by the frame's left edge and whose far heads are a few pixels, in
// both modes. Leaving one visible character's rectangle out of
// characterRegions fails it with 2,841 unlit pixels.
//
// A character whose every slot scatters in the lighting pass (the
// pre-integrated technique) is left out of the pass's first draw, and the
// second draw lights it: only while that slot is visible. With SSS off
// the technique must change nothing.
#include "RenderFixture.h"

#include "scene/SceneEnums.h"

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

TEST_F(CharacterRegions, WithSssOffEveryTechniqueGivesTheSameImage) {
    // SSS off, every technique's image is the plain lighting: the same to the
    // bit (the same programs draw it). The pre-integrated technique's head
    // came out black (every diffuse pixel 0) when the lighting pass left it
    // out of its first draw while SSS off left its slot invisible, so that
    // the second draw never ran; the bound is exact.
    constexpr int kWidth = 160;
    constexpr int kHeight = 90;
    for (const char* mode : {"ss", "ts"}) {
        load("default.json", {std::string("mode=") + mode, "sss.enabled=false", "sss.technique=gaussians"});
        const Image plain = render(Aov::Diffuse, kWidth, kHeight);
        double plainSum = 0.0;
        for (const glm::vec4& t : plain.texels) plainSum += t.r;
        ASSERT_GT(plainSum, 100.0) << mode;  // a lit head, not a black frame
        for (const auto& technique : kSssTechniques) {
            load("default.json", {std::string("mode=") + mode, "sss.enabled=false",
                                  std::string("sss.technique=") + std::string(technique.name)});
            const Image image = render(Aov::Diffuse, kWidth, kHeight);
            ASSERT_EQ(image.texels.size(), plain.texels.size());
            float largest = 0.0f;
            for (size_t i = 0; i < image.texels.size(); ++i)
                largest = std::max(largest, glm::length(glm::vec3(image.texels[i]) - glm::vec3(plain.texels[i])));
            EXPECT_EQ(largest, 0.0f) << mode << " " << technique.name;
        }
    }
}

}  // namespace
