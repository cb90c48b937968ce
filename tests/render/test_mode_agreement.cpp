// Screen-space and texture-space mode render the same scene: every image the
// two share must agree (docs/texture-space.md, "What both modes share"). The
// background, the G-buffer's AOVs (object, albedo, normal, depth), the
// lighting pass's (irradiance, ao, specular) and, with SSS off, the whole
// frame come from the same passes on the same inputs, so they must be the
// same to the bit; with SSS on, the texture-space passes change only the
// SSS characters' diffuse light. Texture space renders as variant c (LEAN is
// screen space only), so its screen-space side here is variant c.
//
// 320 x 180 rather than 160 x 90: a pixel of the head covers 1.5 mm instead
// of 3, so more of the diffuse light comes through the texture-space blurs
// (the studio's planted energy error below showed 1.24% instead of 0.68%).
// At both sizes green and blue sit mostly in Gaussians under a texel wide,
// which the gather takes from the pixel's own light.
#include "RenderFixture.h"
#include "TestContent.h"
#include "TestSupport.h"

#include "core/ImageMetrics.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

using namespace dermis;

namespace {

constexpr int kWidth = 320;
constexpr int kHeight = 180;
// One step of the 8-bit output: the goal for the final image's background.
constexpr double kOneStep = 1.0 / 255.0;

const std::vector<std::string> kStudio = {"lights=[]", R"(environment={"source": "studio"})"};

// The AOVs that read no texture-space pass in either mode.
const std::vector<Aov> kSharedAovs = {Aov::Object, Aov::Albedo,     Aov::Normal,  Aov::Depth,
                                      Aov::Ao,     Aov::Irradiance, Aov::Specular};

class ModeAgreement : public test::RenderFixture {
protected:
    // Each of `aovs` in one mode, one frame each at `timeS`, from the scene loaded.
    std::map<Aov, Image> renderIn(SssMode mode, SssVariant variant, const std::vector<Aov>& aovs, float timeS) {
        mScene->settings.mode = mode;
        mScene->settings.sss.variant = variant;
        std::map<Aov, Image> images;
        for (Aov aov : aovs) {
            FrameRequest request{kWidth, kHeight, aov};
            request.timeS = timeS;
            const Status status = mRenderer->renderFrame(request);
            EXPECT_TRUE(status.ok()) << status.error().message();
            auto image = mRenderer->readOutput();
            EXPECT_TRUE(image.ok());
            if (image.ok()) images[aov] = std::move(*image);
        }
        return images;
    }

    // Both modes' `aovs` of one loaded scene, screen space first with the object
    // AOV for the masks. Texture space renders as variant c whatever the
    // setting: its side keeps the scene's (the default, lbb), so that the
    // variant would show if it leaked in.
    void renderBoth(const std::string& scene, const std::vector<std::string>& overrides, const std::vector<Aov>& aovs,
                    float timeS = 0.0f, size_t characters = 0) {
        auto loaded = loadScene(scene.find('/') == std::string::npos ? test::contentScene(scene) : scene, overrides);
        ASSERT_TRUE(loaded.ok()) << loaded.error().message();
        if (characters > 0) loaded->characters.resize(characters);
        use(std::move(*loaded));
        ASSERT_TRUE(mRenderer);
        const SssVariant sceneVariant = mScene->settings.sss.variant;
        std::vector<Aov> withIds = {Aov::Object};
        for (Aov aov : aovs) {
            if (aov != Aov::Object) withIds.push_back(aov);
        }
        mSs = renderIn(SssMode::ScreenSpace, SssVariant::C, withIds, timeS);
        mTs = renderIn(SssMode::TextureSpace, sceneVariant, aovs, timeS);
        const Image& ids = mSs[Aov::Object];
        mBackground.assign(ids.texels.size(), 0);
        mCharacters.assign(ids.texels.size(), 0);
        for (size_t i = 0; i < ids.texels.size(); ++i) {
            const bool background = std::lround(ids.texels[i].r) == 0;
            mBackground[i] = background ? 1 : 0;
            mCharacters[i] = background ? 0 : 1;
        }
    }

    // ts against ss over `mask` (every pixel when empty), printed with `label`.
    ImageDifference difference(Aov aov, const std::vector<uint8_t>& mask, const std::string& label) {
        auto compared = compareImages(mSs[aov], mTs[aov], mask);
        EXPECT_TRUE(compared.ok()) << label << ": " << (compared.ok() ? "" : compared.error().message());
        if (!compared.ok()) return {};
        std::printf("[ measured ] %s, %s: %zu pixels, largest difference %.3g (peak %.3g), relative RMSE %.4f\n",
                    label.c_str(), std::string(kAovs.name(aov)).c_str(), compared->pixels,
                    compared->maxAbsDifference, compared->peak, compared->relativeRmse);
        return *compared;
    }

    // Every AOV of kSharedAovs the same in both modes, every pixel.
    void expectSharedAovsIdentical(const std::string& label) {
        for (Aov aov : kSharedAovs) {
            const ImageDifference d = difference(aov, {}, label);
            // The same passes on the same inputs: bit for bit (measured 0 for each).
            // Texture-space mode given the LEAN frame of the scene's variant
            // (frameUsesLean ignoring the mode) moved the three heads' normal AOV by
            // 0.0037 and their irradiance by 0.058, and broke both scenes' specular.
            EXPECT_EQ(d.maxAbsDifference, 0.0) << label << ", " << kAovs.name(aov);
        }
    }

    // SSS on: the background of the final frame the same, the characters' diffuse
    // light within the techniques' difference: at depth edges and silhouettes
    // the screen-space blur stops and texture space does not
    // (docs/texture-space.md). Scenes with a back light run with transmittance
    // off: screen space blurs the transmitted light once more, texture space
    // adds it after its gather, and the ears differ by up to 0.26.
    void expectOnlyTheSkinsDiffuseDiffers(const std::string& label) {
        EXPECT_LE(difference(Aov::Final, mBackground, label + ", background").maxAbsDifference, kOneStep) << label;
        const ImageDifference diffuse = difference(Aov::Diffuse, mCharacters, label + ", SSS on");
        // Measured 0.0036 (bent cylinder), 0.0063 (head in the studio), 0.0079
        // (three heads): the blurs' different neighbourhoods at depth edges and
        // silhouettes, and as much again elsewhere. 1.2%: the gathers reading their
        // textures 0.01 in v away from the surface's UV (about 2.5 texels) gave
        // 0.040 (studio) and 0.025 (three heads) and failed. It cannot see a
        // character's SSS missing at this scale: with the near head's gather
        // skipped (its diffuse the unblurred irradiance) it read 0.0083, as the
        // SSS changes these views by about as much as the two techniques differ;
        // the gathers are counted instead (SeveralCharacters...). The thin-edge
        // fill (include/ThinEdges.glsl), which the two modes apply their own way
        // (to screen-space taps past an outline, to the gather's Gaussians near a
        // chart border), moved the three heads to 0.0124; texture space then
        // took the far side's light across the ear's rim seam from its own
        // texture instead of the hidden-side pass's estimate (ts_gather.frag),
        // which brought its ear closer to the matched reference
        // (ThinEdges.EarRim..., ts 3.96% -> 3.51%) and the three heads to
        // 0.0168, on the outermost pixels of the near head's ear rim: 1.8%,
        // which still fails both broken gathers above.
        EXPECT_LT(diffuse.relativeRmse, 0.018) << label;
        glm::dvec3 ssSum(0.0), tsSum(0.0);
        for (size_t i = 0; i < mCharacters.size(); ++i) {
            if (!mCharacters[i]) continue;
            ssSum += glm::dvec3(mSs[Aov::Diffuse].texels[i]);
            tsSum += glm::dvec3(mTs[Aov::Diffuse].texels[i]);
        }
        const glm::dvec3 ratio = tsSum / ssSum;
        std::printf("[ measured ] %s: ts / ss diffuse summed over the characters %.4f %.4f %.4f\n", label.c_str(),
                    ratio.r, ratio.g, ratio.b);
        // Both blurs keep the light's energy, so the sums agree: measured within
        // 0.17% (red, bent cylinder). 0.25%: the texture-space irradiance without
        // its energy conservation factor (1 - rho_s rho_dt) raised red by 0.32%
        // (three heads), 0.81% (cylinder) and 1.24% (studio) and failed all three;
        // green and blue, mostly in Gaussians under a texel, moved by 1e-4.
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], 1.0, 0.0025) << label << ", channel " << c;
    }

    std::map<Aov, Image> mSs, mTs;
    std::vector<uint8_t> mBackground, mCharacters;
};

size_t count(const std::vector<uint8_t>& mask) { return size_t(std::count(mask.begin(), mask.end(), uint8_t(1))); }

}  // namespace

// The environment is drawn behind the characters by the skybox pass in both
// modes. Texture space once drew a flat colour with a strip of its pixel
// irradiance instead: the gather had bound that to the environment map's unit.
TEST_F(ModeAgreement, EnvironmentBackgroundIsTheSameSky) {
    renderBoth("default.json", kStudio, {Aov::Final, Aov::Radiance, Aov::Irradiance, Aov::Specular, Aov::Diffuse});
    ASSERT_GT(count(mBackground), 5000u);
    ASSERT_TRUE(pass("skybox") && pass("skybox")->executed) << "texture space drew no sky";

    // 1/255, the goal; the same program on the same inputs (measured 0). With the
    // gather on unit 11 the final background was off by up to 197/255.
    EXPECT_LE(difference(Aov::Final, mBackground, "studio background").maxAbsDifference, kOneStep);
    // The linear frame, which the tone curve and 8 bits do not round: bit for bit
    // (measured 0; with the gather on unit 11, 1.31).
    EXPECT_EQ(difference(Aov::Radiance, mBackground, "studio background").maxAbsDifference, 0.0);
    // The sky is not flat (both modes drawing one colour would pass the above).
    float lowest = 1e9f, highest = 0.0f;
    for (size_t i = 0; i < mBackground.size(); ++i) {
        if (!mBackground[i]) continue;
        lowest = std::min(lowest, mTs[Aov::Radiance].texels[i].g);
        highest = std::max(highest, mTs[Aov::Radiance].texels[i].g);
    }
    std::printf("[ measured ] studio background, green from %.4f to %.4f\n", lowest, highest);
    // The skybox drawing one grey gave 0 and failed.
    EXPECT_GT(highest - lowest, 0.02f) << "the studio map varies over this view";

    // The environment's light: the SH irradiance and the prefiltered specular.
    for (Aov aov : {Aov::Irradiance, Aov::Specular}) {
        EXPECT_EQ(difference(aov, {}, "studio").maxAbsDifference, 0.0) << kAovs.name(aov);
    }
    expectOnlyTheSkinsDiffuseDiffers("head in the studio");
}

// Several characters: crowd8_mixed.json's first three heads (one near, two
// further off, partly hidden) under the default lights, SSS on, so the texture-space
// passes run for three characters.
TEST_F(ModeAgreement, SeveralCharactersShareEverythingButTheSkinsDiffuseLight) {
    std::vector<Aov> aovs = kSharedAovs;
    aovs.push_back(Aov::Diffuse);
    aovs.push_back(Aov::Final);
    renderBoth("crowd8_mixed.json", {"transmittance.enabled=false"}, aovs, 0.0f, 3);
    ASSERT_EQ(mScene->characters.size(), 3u);
    ASSERT_GT(count(mCharacters), 3000u);
    expectSharedAovsIdentical("three heads");
    expectOnlyTheSkinsDiffuseDiffers("three heads");
    // Each head's light is gathered from its own texture (skipping the near
    // head's gather failed this, and passed the bounds above).
    int gathers = 0;
    for (const PassSummary& s : summary()) {
        const bool gather = s.name.rfind("ts ", 0) == 0 && s.name.size() > 7 && s.name.substr(s.name.size() - 7) == " gather";
        gathers += gather && s.executed ? 1 : 0;
    }
    EXPECT_EQ(gathers, 3);
}

// The bending cylinder (test/TestContent.h) at 1 s, bent 90 degrees: both
// modes draw the skinned vertex buffer.
TEST_F(ModeAgreement, AnAnimatedCharacterSharesEverythingButItsDiffuseLight) {
    test::TempDir dir;
    ASSERT_TRUE(test::writeBendingCylinder(dir.file("bending_cylinder.gltf")));
    test::writeTextFile(dir.file("cylinder.json"), R"({
  "camera": {"position_m": [0.0, 0.12, 0.3], "target_m": [0.03, 0.1, 0.0], "vertical_fov_deg": 35},
  "lights": [{"type": "directional", "direction": [-0.5, -0.4, -0.75], "shadow": true}],
  "characters": [{"name": "cylinder", "mesh": {"gltf": "bending_cylinder.gltf"}, "animation": {"clip": "bend"}}]
})");
    std::vector<Aov> aovs = kSharedAovs;
    aovs.push_back(Aov::Diffuse);
    aovs.push_back(Aov::Final);
    renderBoth(dir.file("cylinder.json"), {}, aovs, 1.0f);
    ASSERT_GT(count(mCharacters), 1000u);
    expectSharedAovsIdentical("bent cylinder");
    expectOnlyTheSkinsDiffuseDiffers("bent cylinder");
}

// With SSS off texture space runs no blur and no gather: its diffuse light
// and its final frame are screen space's, characters included.
TEST_F(ModeAgreement, WithSssOffBothModesGiveTheSameImage) {
    for (const std::vector<std::string>& light : {std::vector<std::string>{}, kStudio}) {
        std::vector<std::string> overrides = light;
        overrides.push_back("sss.enabled=false");
        const std::string label = light.empty() ? "head, SSS off" : "head in the studio, SSS off";
        renderBoth("default.json", overrides, {Aov::Diffuse, Aov::Radiance, Aov::Final});
        ASSERT_GT(count(mCharacters), 3000u);
        // The same passes (measured 0). The texture-space passes left running
        // with SSS off (TsPlan ignoring sss.enabled) moved the diffuse by up to
        // 1.26 (lights, the TSM's back light included) and 0.31 (studio).
        EXPECT_EQ(difference(Aov::Diffuse, {}, label).maxAbsDifference, 0.0) << label;
        EXPECT_EQ(difference(Aov::Radiance, {}, label).maxAbsDifference, 0.0) << label;
        EXPECT_LE(difference(Aov::Final, {}, label).maxAbsDifference, kOneStep) << label;
    }
}
