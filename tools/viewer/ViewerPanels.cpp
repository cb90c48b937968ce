// Panels for the viewer itself: the view and A/B comparison, effect switches, saving, shaders, keys.
#include "viewer/Keys.h"
#include "viewer/PanelWidgets.h"
#include "viewer/Panels.h"
#include "viewer/SceneJson.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace dermis::viewer {
namespace {

const ImVec4 kErrorColour{1.0f, 0.4f, 0.35f, 1.0f};
const ImVec4 kOkColour{0.5f, 0.9f, 0.5f, 1.0f};

struct BPreset {
    const char* label;
    const char* pointer;  // a scene key, set through the loader so that a key this build lacks is refused
    const char* value;    // JSON
};

// One-click comparisons: B becomes A with one change.
const std::vector<BPreset>& bPresets() {
    static const std::vector<BPreset> kPresets = {
        {"texture-space SSS (SS | TS)", "/settings/mode", "\"ts\""},
        {"control blur (Jimenez)", "/settings/sss/blur", "\"control\""},
        {"bilateral blur", "/settings/sss/blur", "\"bilateral\""},
        {"LEAN variant C (Jimenez)", "/settings/sss/variant", "\"c\""},
        {"LEAN variant LCB", "/settings/sss/variant", "\"lcb\""},
        {"SSS off", "/settings/sss/enabled", "false"},
        {"transmittance off", "/settings/transmittance/enabled", "false"},
        {"SSAO off", "/settings/ssao/enabled", "false"},
        {"energy conservation off", "/settings/energy_conservation", "false"},
        {"3 Gaussians", "/settings/sss/gaussians", "3"},
        {"17 taps", "/settings/sss/taps", "17"},
    };
    return kPresets;
}

void applyPreset(ViewerState& state, const BPreset& preset, const Scene& a, Scene& b) {
    Scene candidate = a;
    const Status set = setSceneValue(candidate, preset.pointer, nlohmann::json::parse(preset.value));
    if (!set.ok()) {
        state.report(std::string("B = A with ") + preset.label + ": not in this build: " + set.error().message(), true);
        return;
    }
    b = std::move(candidate);
}

void comparisonControls(ViewerState& state, Scene& a, Scene& b, const std::vector<SceneDifference>& differences) {
    int target = static_cast<int>(state.editTarget);
    ImGui::TextUnformatted("panels edit");
    ImGui::SameLine();
    ImGui::RadioButton("A", &target, static_cast<int>(EditTarget::A));
    ImGui::SameLine();
    ImGui::RadioButton("B", &target, static_cast<int>(EditTarget::B));
    ImGui::SameLine();
    ImGui::RadioButton("both", &target, static_cast<int>(EditTarget::Both));
    state.editTarget = static_cast<EditTarget>(target);
    if (ImGui::Button("copy A to B")) state.requests.copyAToB = true;
    ImGui::SameLine();
    if (ImGui::Button("copy B to A")) state.requests.copyBToA = true;
    if (ImGui::BeginCombo("B = A with", "choose...")) {
        for (const BPreset& preset : bPresets()) {
            if (ImGui::Selectable(preset.label)) applyPreset(state, preset, a, b);
        }
        ImGui::EndCombo();
    }
    if (state.mode == ViewMode::Split) {
        ImGui::SliderFloat("divider", &state.dividerFraction, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    } else {
        ImGui::SliderFloat("difference x", &state.differenceScale, 1.0f, 1000.0f, "%.0f",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        widgets::help("Shows max over RGB of |A - B| (as displayed, in [0, 1]) times this, black-blue-green-yellow-red.");
    }
    if (differences.empty()) {
        ImGui::TextDisabled("B does not differ from A.");
        return;
    }
    ImGui::TextUnformatted("B differs from A in:");
    if (ImGui::BeginTable("differences", 3, ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("key");
        ImGui::TableSetupColumn("A");
        ImGui::TableSetupColumn("B");
        ImGui::TableHeadersRow();
        for (const SceneDifference& d : differences) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(d.key.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(d.a.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(d.b.c_str());
        }
        ImGui::EndTable();
    }
}

}  // namespace

void viewPanel(ViewerState& state, Scene& a, Scene& b, const std::vector<SceneDifference>& differences,
               float cameraDistanceM) {
    int mode = static_cast<int>(state.mode);
    ImGui::RadioButton("single", &mode, static_cast<int>(ViewMode::Single));
    ImGui::SameLine();
    ImGui::RadioButton("A|B split", &mode, static_cast<int>(ViewMode::Split));
    ImGui::SameLine();
    ImGui::RadioButton("difference", &mode, static_cast<int>(ViewMode::Difference));
    state.mode = static_cast<ViewMode>(mode);

    const std::string current(kAovs.name(state.aov));
    if (ImGui::BeginCombo("AOV", current.c_str())) {
        for (const AovChoice& choice : aovChoices()) {
            const bool selected = choice.aov == state.aov;
            if (ImGui::Selectable(choice.name.c_str(), selected) && !selected) state.setAov(choice.aov, cameraDistanceM);
        }
        ImGui::EndCombo();
    }
    widgets::help("The component shown, before tone mapping (final: the tone-mapped frame). n / m step through them. "
                  "stretch and irradiance-texture show the first SSS character on screen in its UV layout (the unit "
                  "square letterboxed, v up) in either mode; in screen-space mode only their own texture-space passes "
                  "run. Black when SSS is off or no SSS character is on screen.");
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", std::string(kAovs.description(state.aov)).c_str());
    ImGui::PopTextWrapPos();
    if (state.aovMapping.transform != DisplayTransform::AsStored) {
        const std::string label = std::string("display range") + (*state.aovMapping.unit ? " (" : "") +
                                  state.aovMapping.unit + (*state.aovMapping.unit ? ")" : "");
        // Half a per cent of the range per pixel dragged, so that ranges in the
        // hundreds (the stretch map's mm) move as easily as [-1, 1].
        const glm::vec2 range = state.aovMapping.range;
        ImGui::DragFloat2(label.c_str(), &state.aovMapping.range.x, std::max(0.005f * std::abs(range.y - range.x), 1e-4f));
        ImGui::SameLine();
        if (ImGui::SmallButton("reset")) state.setAov(state.aov, cameraDistanceM);
    }
    if (state.comparing()) comparisonControls(state, a, b, differences);
}

void effectsPanel(ViewerState& state, const Scene& scene) {
    EffectSwitches& switches = state.switches;
    if (switches.lights.size() < scene.lights.size()) switches.lights.resize(scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const std::string label = "light " + std::to_string(i) + (i < 10 ? "  [" + std::to_string(i) + "]" : "");
        ImGui::Checkbox(label.c_str(), &switches.lights[i].on);
        if (i % 2 == 0 && i + 1 < scene.lights.size()) ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    }
    ImGui::Checkbox("specular  [z]", &switches.specular);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::Checkbox("shadows  [o]", &switches.shadows);
    ImGui::Checkbox("SSS  [b]", &switches.sss);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::Checkbox("transmittance  [y]", &switches.transmittance);
    ImGui::Checkbox("ambient  [e]", &switches.ambient);
    ImGui::SameLine(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::Checkbox("SSAO  [q]", &switches.ssao);
    widgets::help("Switches act on both A and B and are not saved: the saved scene keeps the panels' values.");
}

void savePanel(ViewerState& state) {
    ImGui::InputText("##screenshot", &state.screenshotPath);
    ImGui::SameLine();
    if (ImGui::Button("screenshot")) state.requests.screenshot = true;
    widgets::help("The whole window, panels included, as PNG. Key p.");
    ImGui::InputText("##scene", &state.sceneJsonPath);
    ImGui::SameLine();
    if (ImGui::Button("save scene")) state.requests.saveScene = true;
    widgets::help("The edited settings (A, or B when the panels edit B) as a scene JSON file, with the current camera.");
    if (!state.message.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(state.messageIsError ? kErrorColour : kOkColour, "%s", state.message.c_str());
        ImGui::PopTextWrapPos();
    }
}

void shaderPanel(ViewerState& state, const std::string& shaderDirectory) {
    ImGui::Checkbox("reload on change", &state.watchShaders);
    ImGui::SameLine();
    if (ImGui::Button("reload now")) state.requests.reloadShaders = true;
    ImGui::TextDisabled("%s", shaderDirectory.c_str());
    if (state.shaderError.empty()) {
        ImGui::TextColored(kOkColour, "shaders compiled");
    } else {
        ImGui::TextColored(kErrorColour, "compile error; the previous programs stay in use:");
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(state.shaderError.c_str());
        ImGui::PopTextWrapPos();
    }
}

void keysPanel() {
    auto table = [](const char* id, const std::vector<KeyHelp>& rows) {
        if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingFixedFit)) return;
        for (const KeyHelp& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row.keys);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(row.action);
        }
        ImGui::EndTable();
    };
    table("mouse", mouseHelp());
    ImGui::Separator();
    table("keys", keyHelp());
}

}  // namespace dermis::viewer
