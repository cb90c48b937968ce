// The light past the outline of a thin part (shaders/include/ThinEdges.glsl):
// against the matched reference on the procedural head's ear in both modes,
// and left alone where the part is thick.
#include "RenderFixture.h"
#include "TestSupport.h"

#include "core/ImageMetrics.h"
#include "measure/MeasuredRender.h"
#include "reference/ReferenceRenderer.h"

#include <cmath>
#include <cstdio>

using namespace dermis;

namespace {

class ThinEdges : public test::RenderFixture {};

constexpr int kWidth = 160;
constexpr int kHeight = 90;

}  // namespace

// The ear seen face on from 20 cm (content/scenes/ear_closeup.json), front-lit
// by the key light, its far rim lit from behind by the spot. The matched
// reference scatters the engine's own irradiance over the mesh by 3-D
// distance, so its rim loses light to the dark back of the ear and gains it
// from a lit one; each mode's scatter error against it, over the SSS pixels,
// with the thin-edge fill and without.
TEST_F(ThinEdges, EarRimScattersCloserToTheMatchedReferenceInBothModes) {
    load("ear_closeup.json", {"ssao.enabled=false", "sss.enabled=false"});
    const Image unscattered = render(Aov::Diffuse, kWidth, kHeight);
    const auto mask = measure::sssMask(*mRenderer, kWidth, kHeight);
    ASSERT_TRUE(mask.ok()) << mask.error().message();

    load("ear_closeup.json", {"ssao.enabled=false"});
    render(Aov::Diffuse, kWidth, kHeight);
    auto irradiance = mRenderer->captureIrradianceTextures(2048);
    ASSERT_TRUE(irradiance.ok()) << irradiance.error().message();
    reference::ReferenceOptions options;
    options.engineIrradiance = std::move(*irradiance);
    options.samplesPerPixel = 4;  // as `compare --errors` (--change-spp 4)
    auto reference = reference::ReferenceRenderer::load(*mScene, options);
    ASSERT_TRUE(reference.ok()) << reference.error().message();
    Image matched = reference->renderScatterChange(kWidth, kHeight);
    ASSERT_EQ(matched.texels.size(), unscattered.texels.size());
    for (size_t i = 0; i < matched.texels.size(); ++i) matched.texels[i] += unscattered.texels[i];

    double error[2][2];  // [mode][thin edges]
    for (int mode = 0; mode < 2; ++mode) {
        for (int thin = 0; thin < 2; ++thin) {
            load("ear_closeup.json", {"ssao.enabled=false", mode == 0 ? "mode=ss" : "mode=ts",
                                      thin ? "transmittance.thin_edges=true" : "transmittance.thin_edges=false"});
            const Image image = render(Aov::Diffuse, kWidth, kHeight);
            auto difference = compareImages(matched, image, *mask);
            ASSERT_TRUE(difference.ok()) << difference.error().message();
            error[mode][thin] = difference->relativeRmse;
        }
        std::printf("%s: scatter error %.3f%% without the fill, %.3f%% with it\n", mode == 0 ? "ss" : "ts",
                    100.0 * error[mode][0], 100.0 * error[mode][1]);
    }
    // Measured (160x90, the change at 2048^2 and spp 4): ss 3.83% -> 3.31%, ts
    // 4.17% -> 3.33% (texture space reads the far side's light across the
    // ear's rim seam from its own texture, and leaves the surface inside the
    // body out of its blurs; with neither, 4.30% -> 3.96% with the
    // transmittance's former 6 taps per ring). The rest is the back-lit rim,
    // too dark in both modes. Broken on purpose through copies of the
    // shaders: the hidden side's full light (THIN_EDGE_BACK_SHARE 1) gives
    // 5.58% and 4.32%, the rim's full light (THIN_EDGE_RIM_SHARE 1) 4.89% and
    // 3.60%. So screen space must fall by a tenth and texture space by 17%
    // (3.46%: between what it measures and the second break).
    EXPECT_LT(error[0][1], 0.9 * error[0][0]);
    EXPECT_LT(error[1][1], 0.83 * error[1][0]);
}

// The wedge of content/scenes/slab.json seen from above (1 mm thick at
// x = 0, 20 mm at x = 0.2 m), lit from above and from below. Where the view
// ray's path through it is over THIN_EDGE_NONE_MM (8 mm: x > 0.074 m, image
// columns from 70 on at 160x90, 2.6 mm per pixel) the fill's weight is 0 and
// every pixel is the same to the bit with the fill and without; along the thin
// end's outline (columns 42-52, under 4 mm) it changes the light.
TEST_F(ThinEdges, OnlyThinPartsChangeInBothModes) {
    for (const char* mode : {"mode=ss", "mode=ts"}) {
        Image image[2];
        for (int thin = 0; thin < 2; ++thin) {
            load("slab.json", {mode, thin ? "transmittance.thin_edges=true" : "transmittance.thin_edges=false"});
            image[thin] = render(Aov::Diffuse, kWidth, kHeight);
        }
        int thickChanged = 0;
        int thinChanged = 0;
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                const glm::vec4 a = image[0].at(x, y);
                const glm::vec4 b = image[1].at(x, y);
                const float scale = std::max(std::max(a.r, a.g), std::max(a.b, 1e-6f));
                const float change = std::max(std::abs(a.r - b.r), std::max(std::abs(a.g - b.g), std::abs(a.b - b.b)));
                if (x >= 72 && change > 0.0f) ++thickChanged;
                if (x >= 42 && x <= 52 && change > 0.01f * scale) ++thinChanged;
            }
        }
        std::printf("%s: %d pixels changed over the thick part, %d by more than 1%% along the thin end\n", mode,
                    thickChanged, thinChanged);
        // Broken on purpose: without the path test (THIN_EDGE_NONE_MM 1e9) 565 (ss) and 6 (ts)
        // pixels change there; without the normal test (THIN_EDGE_OPPOSED_* below -1) 600 and
        // 378. Texture space takes the light across the wedge's seams where the chart
        // beyond reaches 1.5 mm (mesh/UvLayout.h), whatever the switch; its 1 mm thin end
        // does not, and takes the hidden-side fill: 19 pixels change there.
        EXPECT_EQ(thickChanged, 0) << mode;
        EXPECT_GT(thinChanged, 4) << mode;
    }
}
