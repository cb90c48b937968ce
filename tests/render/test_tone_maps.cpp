// The tone maps of settings.tone_map (shaders/tonemap.frag) on a grey
// background of known radiance, against each curve's value worked out from
// its published definition: the final image is 8-bit sRGB, so each value is
// expected within 1/255 (the 8-bit rounding, 0.5/255, plus float error).
// Halving ACES's 2.51 or dropping PBR Neutral's 0.04 offset moves these by
// 4/255 or more.
#include "RenderFixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace dermis {
namespace {

double encodeSrgb(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

struct Expected {
    const char* toneMap;
    double radiance;
    double display;  // linear display value before the sRGB encoding
};

// ACES (Narkowicz 2016): x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14).
//   0.5: 0.6425 / 1.0425 = 0.616307;  4: 40.28 / 41.38 = 0.973417.
// PBR Neutral (Khronos 2024): 0.5 - 0.04 = 0.46 is below the 0.76 start of
//   compression; 4 - 0.04 = 3.96 peaks at 1 - 0.24^2 / (3.96 + 0.24 - 0.76) = 0.983256,
//   and a grey stays grey whatever the desaturation.
// AgX (Sobotka 2022, Wrensch 2023's fit): its inset matrix, log2 encoding over
//   [-12.47393, 4.026069] EV, polynomial, outset matrix and 2.2 power,
//   evaluated in double precision with numpy from the published constants:
//   0.5 -> 0.425127, 4 -> 0.860884 (channel means; the channels differ by 2e-4).
// None: clamped: 0.5 and 1.
const Expected kExpected[] = {
    {"aces", 0.5, 0.6425 / 1.0425},     {"aces", 4.0, 40.28 / 41.38},
    {"pbr-neutral", 0.5, 0.46},         {"pbr-neutral", 4.0, 1.0 - 0.0576 / 3.44},
    {"agx", 0.5, 0.425127},             {"agx", 4.0, 0.860884},
    {"none", 0.5, 0.5},                 {"none", 4.0, 1.0},
};

class ToneMaps : public test::RenderFixture {};

TEST_F(ToneMaps, AGreyBackgroundLandsOnEachCurve) {
    for (const Expected& e : kExpected) {
        const std::string grey = std::to_string(e.radiance);
        load("default.json", {"characters=[]", "tone_map=" + std::string(e.toneMap),
                              "background={\"colour\": [" + grey + ", " + grey + ", " + grey + "]}"});
        const Image image = render(Aov::Final, 16, 9);
        ASSERT_EQ(image.texels.size(), 16u * 9u);
        const double expected = encodeSrgb(e.display);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.texels[4 * 16 + 8][c], expected, 1.0 / 255.0)
                << e.toneMap << " at " << e.radiance << ", channel " << c;
        }
    }
}

}  // namespace
}  // namespace dermis
