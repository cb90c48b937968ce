// The environment panel: the source (none, a built-in map or a lat-long file),
// its intensity and rotation, the background, and how its light is occluded
// and reflected (docs/environment.md).
#include "viewer/PanelWidgets.h"
#include "viewer/Panels.h"

#include "core/Limits.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>
#include <string>
#include <vector>

namespace dermis::viewer {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr const char* kNoSource = "none";
constexpr const char* kFileSource = "file...";
constexpr float kMaxIntensity = 100.0f;
constexpr float kMaxAngleDeg = 180.0f;
constexpr float kMinAxisLength = 1e-6f;  // shorter: the zero vector, refused (as by the loader)

std::vector<std::string> sourceChoices() {
    std::vector<std::string> choices{kNoSource};
    for (std::string_view name : kBuiltInEnvironments) choices.emplace_back(name);
    choices.emplace_back(kFileSource);
    return choices;
}

std::string sourceChoice(const Environment& environment, const EnvironmentEdit& edit) {
    if (edit.fileChosen) return kFileSource;
    if (!environment.enabled()) return kNoSource;
    return isBuiltInEnvironment(environment.source) ? environment.source : kFileSource;
}

// Turning the environment on starts from the defaults (intensity 1 ...), not
// from whatever an earlier, switched-off environment had.
void setSource(Environment& environment, const std::string& source) {
    if (!environment.enabled()) environment = Environment{};
    environment.source = source;
}

bool mapFileField(Environment& environment, EnvironmentEdit& edit) {
    const bool fromFile = environment.enabled() && !isBuiltInEnvironment(environment.source);
    if (edit.file.empty() && fromFile) edit.file = environment.source;
    bool changed = false;
    if (ImGui::InputText("map file", &edit.file, ImGuiInputTextFlags_EnterReturnsTrue) && !edit.file.empty()) {
        setSource(environment, std::filesystem::absolute(edit.file).lexically_normal().string());
        edit.error.clear();
        changed = true;
    }
    widgets::help("A lat-long radiance map (.hdr, .exr, .png ...); press Enter to load it. A relative path is from "
                  "the current directory. A map that fails to load leaves the previous environment in place.");
    if (!edit.error.empty()) {
        ImGui::PushTextWrapPos();
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "not loaded: %s", edit.error.c_str());
        ImGui::PopTextWrapPos();
    }
    return changed;
}

bool sourceWidgets(Environment& environment, EnvironmentEdit& edit) {
    static const std::vector<std::string> kChoices = sourceChoices();
    std::string choice = sourceChoice(environment, edit);
    bool changed = false;
    if (widgets::comboString("source", choice, kChoices)) {
        edit.fileChosen = choice == kFileSource;
        if (choice == kNoSource) {
            environment.source.clear();
            changed = true;
        } else if (!edit.fileChosen) {
            setSource(environment, choice);
            changed = true;
        }
    }
    widgets::help("none: only the uniform ambient (Frame panel) lights the scene; sky, studio: maps the engine makes; "
                  "file...: a lat-long map file.");
    if (sourceChoice(environment, edit) == kFileSource) changed |= mapFileField(environment, edit);
    return changed;
}

bool rotationWidgets(EnvironmentRotation& rotation) {
    bool changed = false;
    glm::vec3 axis = rotation.axis;
    if (ImGui::DragFloat3("axis", &axis.x, 0.01f, -1.0f, 1.0f, "%.3f") && glm::length(axis) > kMinAxisLength) {
        rotation.axis = glm::normalize(axis);
        changed = true;
    }
    widgets::help("The axis the map turns about, in world space; normalised on edit (the zero vector is refused).");
    changed |= ImGui::SliderFloat("angle", &rotation.angleDeg, -kMaxAngleDeg, kMaxAngleDeg, "%.1f deg", kClamp);
    widgets::help("The angle at time 0: world(d) = R map(d).");
    const float maxSpeed = static_cast<float>(kMaxEnvironmentSpeedDegPerS);
    changed |= ImGui::DragFloat("speed", &rotation.speedDegPerS, 0.5f, -maxSpeed, maxSpeed, "%.1f deg/s", kClamp);
    widgets::help("The angle grows by this per second of scene time (play in the Animation panel).");
    return changed;
}

}  // namespace

bool environmentPanel(Scene& scene, EnvironmentEdit& edit) {
    Environment& environment = scene.environment;
    bool changed = sourceWidgets(environment, edit);
    if (!environment.enabled()) return changed;
    changed |= ImGui::SliderFloat("intensity", &environment.intensity, 0.0f, kMaxIntensity, "%.3f",
                                  ImGuiSliderFlags_Logarithmic | kClamp);
    widgets::help("Multiplies the map's radiance.");
    changed |= rotationWidgets(environment.rotation);
    changed |= ImGui::Checkbox("background", &environment.background);
    widgets::help("Draw the map behind the scene; off: the Frame panel's background colour.");
    changed |= widgets::comboEnum("occlusion", kEnvironmentOcclusions, environment.occlusion);
    widgets::help(std::string(kEnvironmentOcclusions.description(environment.occlusion)).c_str());
    changed |= widgets::comboEnum("specular", kEnvironmentSpeculars, environment.specular);
    widgets::help(std::string(kEnvironmentSpeculars.description(environment.specular)).c_str());
    changed |= widgets::comboEnum("diffuse", kEnvironmentDiffuses, environment.diffuse);
    widgets::help(std::string(kEnvironmentDiffuses.description(environment.diffuse)).c_str());
    changed |= ImGui::SliderInt("SH bands", &environment.shBands, 1, kMaxShBands, "%d", kClamp);
    widgets::help("Bands of the spherical harmonics (1, 4 or 9 coefficients): of the diffuse light with diffuse \"sh\", "
                  "and of the light the transfer's occlusion is weighed with.");
    changed |= widgets::comboEnum("extract light", kEnvironmentLightExtractions, environment.extractLight);
    widgets::help(std::string(kEnvironmentLightExtractions.description(environment.extractLight)).c_str());
    if (environment.extractLight == EnvironmentLightExtraction::Auto) {
        changed |= ImGui::SliderFloat("threshold", &environment.extractThreshold, float(kMinEnvironmentExtractThreshold),
                                      1e4f, "%.1f x mean", ImGuiSliderFlags_Logarithmic | kClamp);
        widgets::help("A light's texels are this many times the map's mean luminance or brighter.");
    }
    return changed;
}

}  // namespace dermis::viewer
