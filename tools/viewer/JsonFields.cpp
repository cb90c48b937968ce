#include "viewer/JsonFields.h"

#include "viewer/ChoiceFields.h"
#include "viewer/PanelWidgets.h"
#include "viewer/SceneJson.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace dermis::viewer {
namespace {

using nlohmann::json;

bool isVector3(const json& value) {
    return value.is_array() && value.size() == 3 &&
           std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); });
}

// Draws one value; on a change, writes the new value into `edited` and its pointer into `where`.
void field(const std::string& key, const std::string& pointer, const json& value, std::string& where, json& edited) {
    auto commit = [&](json v) {
        where = pointer;
        edited = std::move(v);
    };
    ImGui::PushID(pointer.c_str());
    const char* label = key.c_str();
    if (value.is_boolean()) {
        bool v = value.get<bool>();
        if (ImGui::Checkbox(label, &v)) commit(v);
    } else if (value.is_number_integer()) {
        int v = value.get<int>();
        if (ImGui::DragInt(label, &v, 0.25f)) commit(v);
    } else if (value.is_number()) {
        float v = value.get<float>();
        const float speed = std::max(std::abs(v) * 0.01f, 0.001f);
        if (ImGui::DragFloat(label, &v, speed, 0.0f, 0.0f, "%.4g")) commit(v);
    } else if (value.is_string()) {
        std::string v = value.get<std::string>();
        // A closed set is a list, not a text field (viewer/ChoiceFields.h).
        const auto choices = settingsChoices().find(pointer);
        const bool changed = choices != settingsChoices().end()
                                 ? widgets::comboString(label, v, choices->second)
                                 : ImGui::InputText(label, &v, ImGuiInputTextFlags_EnterReturnsTrue);
        if (changed) commit(v);
    } else if (isVector3(value)) {
        float v[3] = {value[0].get<float>(), value[1].get<float>(), value[2].get<float>()};
        if (ImGui::DragFloat3(label, v, 0.01f, 0.0f, 0.0f, "%.3g")) commit(json::array({v[0], v[1], v[2]}));
    } else if (value.is_object()) {
        if (ImGui::TreeNode(label)) {
            for (const auto& [childKey, child] : value.items()) field(childKey, pointer + "/" + childKey, child, where, edited);
            ImGui::TreePop();
        }
    } else {
        ImGui::TextDisabled("%s = %s", label, value.dump().c_str());
    }
    ImGui::PopID();
}

}  // namespace

std::vector<std::string> jsonFieldKeys(const Scene& scene, const std::string& pointer, const std::vector<std::string>& skip) {
    const json document = sceneDocument(scene);
    const json::json_pointer at(pointer);
    std::vector<std::string> keys;
    if (!document.contains(at) || !document.at(at).is_object()) return keys;
    for (const auto& [key, value] : document.at(at).items()) {
        if (std::find(skip.begin(), skip.end(), key) == skip.end()) keys.push_back(key);
    }
    return keys;
}

bool jsonFields(Scene& scene, const std::string& pointer, const std::vector<std::string>& skip, std::string& error) {
    const json document = sceneDocument(scene);
    const json::json_pointer at(pointer);
    if (!document.contains(at) || !document.at(at).is_object()) return false;
    std::string where;
    json edited;
    for (const auto& [key, value] : document.at(at).items()) {
        if (std::find(skip.begin(), skip.end(), key) == skip.end()) field(key, pointer + "/" + key, value, where, edited);
    }
    if (where.empty()) return false;
    if (const Status set = setSceneValue(scene, where, edited); !set.ok()) {
        error = set.error().message();
        return false;
    }
    return true;
}

bool jsonChoice(Scene& scene, const std::string& pointer, const char* label, std::string& error) {
    const auto known = settingsChoices().find(pointer);
    const std::vector<std::string> choices = known != settingsChoices().end() ? known->second : std::vector<std::string>{};
    const json document = sceneDocument(scene);
    const json::json_pointer at(pointer);
    if (!document.contains(at) || !document.at(at).is_string()) return false;
    std::string value = document.at(at).get<std::string>();
    if (!widgets::comboString(label, value, choices)) return false;
    if (const Status set = setSceneValue(scene, pointer, value); !set.ok()) {
        error = set.error().message();
        return false;
    }
    return true;
}

}  // namespace dermis::viewer
