// Panels for the frame settings, one per pass: shadows, SSS, transmittance, SSAO, and the frame itself.
#include "viewer/JsonFields.h"
#include "viewer/PanelWidgets.h"
#include "viewer/Panels.h"

#include "sss/DiffusionProfile.h"

#include <imgui.h>

#include <filesystem>
#include <string>

namespace dermis::viewer {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLogClamp = ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp;

std::string characterLabel(const Character& character, size_t index) {
    return character.name.empty() ? "character " + std::to_string(index) : character.name;
}

void sectionLabel(const char* text) {
    ImGui::Separator();
    ImGui::TextDisabled("%s", text);
}

// The keys of "settings" that have a typed panel of their own.
const std::vector<std::string> kTypedSettingsKeys = {"exposure", "tone_map", "mode", "ambient", "energy_conservation",
                                                     "cull_back_faces", "shadow", "sss", "transmittance", "ssao"};

std::vector<std::string> profileChoices() {
    std::vector<std::string> names = profileNames();
    names.emplace_back(kOpaqueProfile);
    return names;
}

}  // namespace

bool shadowPanel(Scene& scene, std::string& error) {
    ShadowSettings& shadow = scene.settings.shadow;
    bool changed = false;
    changed |= ImGui::SliderInt("map size", &shadow.mapSize, kMinShadowMapSize, kMaxShadowMapSize, "%d texels", kLogClamp);
    changed |= widgets::sliderMetresAsMm("constant bias", shadow.biasConstantM, 0.0f, 10.0f);
    changed |= ImGui::SliderFloat("slope bias", &shadow.biasSlopeTexels, 0.0f, 10.0f, "%.2f texels", kClamp);
    widgets::help("Shadow-map texels (their world size at the point) times tan(angle to the light).");
    changed |= jsonChoice(scene, "/settings/shadow/filter", "filter", error);
    widgets::help("pcf4x4: 4x4 percentage-closer filtering (Chappuis 2011); poisson: rotated Poisson-disc taps (Papanikolaou 2013).");
    return changed;
}

bool sssPanel(Scene& scene, const std::vector<CharacterReport>& reports, std::string& error) {
    bool changed = false;
    changed |= ImGui::Checkbox("enabled", &scene.settings.sss.enabled);
    changed |= widgets::comboEnum("technique", kSssTechniques, scene.settings.sss.technique);
    widgets::help("The screen-space scattering technique (docs/screen-space.md); each has its own sample count below.");
    changed |= widgets::comboEnum("variant", kSssVariants, scene.settings.sss.variant);
    changed |= jsonChoice(scene, "/settings/sss/blur", "blur", error);
    widgets::help("bilateral: taps weighted by their depth difference to the centre (Vila Verde 2015 4.3.2); control: "
                  "Jimenez's lerp towards the centre (Vila Verde 2015 3.2.2); fetch-only: the same fetches, unweighted "
                  "(the bandwidth floor, not a blur).");
    SssSettings& sss = scene.settings.sss;
    changed |= widgets::sliderOdd("taps", sss.taps, kMinBlurTaps, kMaxBlurTaps);
    if (sss.blur == SssBlur::Bilateral) {
        changed |= ImGui::SliderFloat("depth sigma", &sss.bilateralDepthMm, 0.01f, 20.0f, "%.3f mm", kLogClamp);
        widgets::help("Bilateral sensitivity: std dev of the Gaussian in tap-to-centre depth difference. Smaller keeps edges sharper.");
    } else if (sss.blur == SssBlur::Control) {
        changed |= ImGui::SliderFloat("depth scale", &sss.controlDepthScalePerMm, 0.0f, 10.0f, "%.3f /mm", kClamp);
        widgets::help("A tap moves to the centre's value by min(1, scale x |depth difference in mm|).");
    }
    changed |= ImGui::SliderInt("Gaussians used", &sss.gaussians, 1, kMaxProfileGaussians, "%d", kClamp);
    widgets::help("The widest of each profile's Gaussians are dropped first.");
    changed |= ImGui::SliderFloat("width scale", &sss.widthScale, 0.0f, 4.0f, "%.3f", kClamp);
    changed |= ImGui::SliderFloat("min width", &sss.minWidthPx, 0.0f, 4.0f, "%.2f px", kClamp);
    widgets::help("A Gaussian narrower than this (std dev, pixels) at the nearest SSS pixel is skipped.");
    changed |= ImGui::SliderFloat("mix", &sss.mix, 0.0f, 1.0f, "%.2f", kClamp);
    widgets::help("Pre-/post-scatter albedo: albedo^mix before the blur, albedo^(1 - mix) after (Chappuis 2011 2.2.4).");
    static const std::vector<std::string> kTyped = {"enabled", "technique", "variant", "blur", "taps", "bilateral_depth_mm",
                                                    "control_depth_scale_per_mm", "gaussians", "width_scale",
                                                    "min_width_px", "mix"};
    changed |= jsonFields(scene, "/settings/sss", kTyped, error);  // e.g. the LEAN variant, when the format has it
    if (!scene.characters.empty()) sectionLabel("profile per character");
    static const std::vector<std::string> kProfiles = profileChoices();
    for (size_t i = 0; i < scene.characters.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        changed |= widgets::comboString(characterLabel(scene.characters[i], i).c_str(),
                                        scene.characters[i].material.profile, kProfiles);
        ImGui::PopID();
    }
    const QualitySettings& quality = scene.settings.quality;
    sectionLabel(quality.errorBudget > 0.0f ? "choice per character (error budget)" : "choice per character");
    if (quality.errorBudget > 0.0f) {
        ImGui::Text("budget %.3g%%, table %s", 100.0 * quality.errorBudget,
                    std::filesystem::path(quality.table).filename().string().c_str());
        widgets::help("Each character gets the quality table's cheapest choice for its pixels per mm (docs/quality.md).");
    }
    for (const CharacterReport& report : reports) {
        const std::string line = describeCharacterSss(report);
        if (!line.empty()) ImGui::TextDisabled("%s", line.c_str());
    }
    return changed;
}

bool transmittancePanel(TransmittanceSettings& transmittance) {
    bool changed = false;
    changed |= ImGui::Checkbox("enabled", &transmittance.enabled);
    changed |= ImGui::SliderFloat("shrink", &transmittance.shrinkMm, 0.0f, 10.0f, "%.2f mm", kClamp);
    widgets::help("The point moves this far inwards along -N before the shadow-map lookup.");
    changed |= ImGui::SliderFloat("strength", &transmittance.strength, 0.0f, 10.0f, "%.2f", kClamp);
    return changed;
}

bool ssaoPanel(Scene& scene) {
    SsaoSettings& ssao = scene.settings.ssao;
    bool changed = false;
    changed |= ImGui::Checkbox("enabled", &ssao.enabled);
    changed |= ImGui::SliderInt("samples", &ssao.samples, kMinSsaoSamples, kMaxSsaoSamples, "%d", kClamp);
    changed |= widgets::sliderMetresAsMm("radius", ssao.radiusM, 0.5f, 200.0f);
    changed |= ImGui::SliderFloat("strength", &ssao.strength, 0.0f, 1.0f, "%.2f", kClamp);
    changed |= ImGui::Checkbox("blur", &ssao.blur);
    if (!scene.characters.empty()) sectionLabel("per character (0 = as above)");
    for (size_t i = 0; i < scene.characters.size(); ++i) {
        CharacterSsao& own = scene.characters[i].ssao;
        ImGui::PushID(static_cast<int>(i));
        ImGui::TextUnformatted(characterLabel(scene.characters[i], i).c_str());
        changed |= widgets::sliderMetresAsMm("radius##own", own.radiusM, 0.0f, 200.0f);
        if (ImGui::SliderInt("samples##own", &own.samples, 0, kMaxSsaoSamples, "%d", kClamp)) {
            if (own.samples > 0 && own.samples < kMinSsaoSamples) own.samples = kMinSsaoSamples;  // 0 or in range
            changed = true;
        }
        ImGui::PopID();
    }
    return changed;
}

bool otherSettingsPanel(Scene& scene, std::string& error) {
    return jsonFields(scene, "/settings", kTypedSettingsKeys, error);
}

bool hasOtherSettings(const Scene& scene) { return !jsonFieldKeys(scene, "/settings", kTypedSettingsKeys).empty(); }

bool framePanel(Scene& scene) {
    RenderSettings& settings = scene.settings;
    bool changed = false;
    changed |= widgets::comboEnum("mode", kSssModes, settings.mode);
    changed |= ImGui::SliderFloat("exposure", &settings.exposure, 0.01f, 16.0f, "%.3f", kLogClamp);
    changed |= widgets::comboEnum("tone map", kToneMaps, settings.toneMap);
    changed |= widgets::colourLinear("ambient", settings.ambient, true);
    widgets::help("Uniform ambient irradiance (linear RGB); SSAO darkens it.");
    changed |= widgets::colourLinear("background", scene.background.colour, true);
    changed |= ImGui::Checkbox("energy conservation", &settings.energyConservation);
    widgets::help("Diffuse x (1 - rho_s rho_dt) where light enters and leaves (Chappuis 2011 2.6).");
    changed |= ImGui::Checkbox("cull back faces", &settings.cullBackFaces);
    widgets::help("The G-buffer skips the back faces of closed meshes seen from outside: the same image, less work.");
    return changed;
}

}  // namespace dermis::viewer
