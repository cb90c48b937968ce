// Panels for the scene's contents: lights, materials, character placement, camera lens.
#include "viewer/Panels.h"
#include "viewer/PanelWidgets.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace dermis::viewer {
namespace {


std::string characterLabel(const Character& character, size_t index) {
    return character.name.empty() ? "character " + std::to_string(index) : character.name;
}

bool lightPanel(Light& light) {
    bool changed = false;
    changed |= widgets::comboEnum("type", kLightTypes, light.type);
    if (light.type != LightType::Directional) {
        changed |= ImGui::DragFloat3("position (m)", &light.positionM.x, 0.005f, -100.0f, 100.0f, "%.3f");
    }
    if (light.type != LightType::Point) changed |= widgets::direction("direction", light.direction);
    changed |= widgets::colourLinear("colour", light.colour, true);
    changed |= ImGui::SliderFloat("intensity", &light.intensity, 0.0f, 100.0f, "%.3f",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (light.type == LightType::Spot) {
        changed |= ImGui::SliderFloat("inner (deg)", &light.spotInnerDeg, 0.0f, 89.9f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
        changed |= ImGui::SliderFloat("outer (deg)", &light.spotOuterDeg, 0.0f, 89.9f, "%.1f", ImGuiSliderFlags_AlwaysClamp);
        light.spotInnerDeg = std::min(light.spotInnerDeg, light.spotOuterDeg);
    }
    changed |= ImGui::Checkbox("casts shadow", &light.castsShadow);
    return changed;
}

}  // namespace

bool lightsPanel(Scene& scene) {
    bool changed = false;
    if (scene.lights.empty()) ImGui::TextDisabled("The scene has no lights.");
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        Light& light = scene.lights[i];
        ImGui::PushID(static_cast<int>(i));
        const std::string label = "light " + std::to_string(i) + " (" + std::string(kLightTypes.name(light.type)) + ")";
        if (ImGui::TreeNodeEx(label.c_str(), i == 0 ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
            changed |= lightPanel(light);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    return changed;
}

bool materialsPanel(Scene& scene) {
    bool changed = false;
    for (size_t i = 0; i < scene.characters.size(); ++i) {
        Material& material = scene.characters[i].material;
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::TreeNodeEx(characterLabel(scene.characters[i], i).c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            changed |= widgets::colourLinear("albedo tint", material.albedo, false);
            widgets::help("Linear albedo; multiplies the albedo map.");
            changed |= ImGui::SliderFloat("roughness m", &material.roughness, 0.01f, 1.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
            widgets::help("Beckmann roughness of the Kelemen/Szirmay-Kalos specular (Chappuis 2011 section 2.3).");
            changed |= ImGui::SliderFloat("rho_s", &material.rhoS, 0.0f, 1.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
            widgets::help("Specular intensity.");
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    return changed;
}

bool charactersPanel(Scene& scene) {
    bool changed = false;
    for (size_t i = 0; i < scene.characters.size(); ++i) {
        Transform& transform = scene.characters[i].transform;
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::TreeNode(characterLabel(scene.characters[i], i).c_str())) {
            changed |= ImGui::DragFloat3("translation (m)", &transform.translationM.x, 0.002f, -100.0f, 100.0f, "%.3f");
            changed |= ImGui::DragFloat3("rotation (deg)", &transform.rotationDeg.x, 0.5f, -360.0f, 360.0f, "%.1f");
            changed |= ImGui::DragFloat("scale", &transform.scale, 0.005f, 0.001f, 1000.0f, "%.3f", ImGuiSliderFlags_AlwaysClamp);
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    return changed;
}

bool cameraPanel(Camera& camera) {
    bool changed = false;
    changed |= ImGui::SliderFloat("vertical fov", &camera.verticalFovDeg, 5.0f, 120.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("near (m)", &camera.nearM, 0.001f, 1.0f, "%.4f",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderFloat("far (m)", &camera.farM, 0.1f, 1000.0f, "%.2f",
                                  ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    if (camera.farM <= camera.nearM) camera.farM = camera.nearM * 2.0f;
    ImGui::Text("eye    %.3f %.3f %.3f", camera.positionM.x, camera.positionM.y, camera.positionM.z);
    ImGui::Text("target %.3f %.3f %.3f", camera.targetM.x, camera.targetM.y, camera.targetM.z);
    return changed;
}

}  // namespace dermis::viewer
