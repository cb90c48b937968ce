#include "viewer/PanelWidgets.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace dermis::viewer::widgets {

bool comboString(const char* label, std::string& value, const std::vector<std::string>& options,
                 const std::vector<std::string>& tooltips) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (size_t i = 0; i < options.size(); ++i) {
            const std::string& option = options[i];
            const bool selected = option == value;
            if (ImGui::Selectable(option.c_str(), selected) && !selected) {
                value = option;
                changed = true;
            }
            if (i < tooltips.size() && !tooltips[i].empty()) hoverTooltip(tooltips[i].c_str());
            if (selected) ImGui::SetItemDefaultFocus();
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool sliderOdd(const char* label, int& value, int lo, int hi) {
    if (!ImGui::SliderInt(label, &value, lo, hi)) return false;
    if (value % 2 == 0) value += 1;
    value = std::clamp(value, lo, hi);
    return true;
}

bool sliderMetresAsMm(const char* label, float& metres, float loMm, float hiMm) {
    float mm = metres * 1000.0f;
    if (!ImGui::SliderFloat(label, &mm, loMm, hiMm, "%.3f mm", ImGuiSliderFlags_AlwaysClamp)) return false;
    metres = mm / 1000.0f;
    return true;
}

bool colourLinear(const char* label, glm::vec3& colour, bool hdr) {
    ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float;
    if (hdr) flags |= ImGuiColorEditFlags_HDR;
    if (!ImGui::ColorEdit3(label, &colour.x, flags)) return false;
    colour = glm::max(colour, glm::vec3(0.0f));
    if (!hdr) colour = glm::min(colour, glm::vec3(1.0f));
    return true;
}

bool direction(const char* label, glm::vec3& dir) {
    const glm::vec3 unit = glm::length(dir) > 0.0f ? glm::normalize(dir) : glm::vec3(0.0f, 0.0f, -1.0f);
    float azimuth = glm::degrees(std::atan2(unit.x, unit.z));
    float elevation = glm::degrees(std::asin(std::clamp(unit.y, -1.0f, 1.0f)));
    ImGui::PushID(label);
    bool changed = ImGui::SliderFloat("azimuth", &azimuth, -180.0f, 180.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp);
    help("The direction the light travels: its angle about +Y (0 = towards +Z).");
    changed |= ImGui::SliderFloat("elevation", &elevation, -90.0f, 90.0f, "%.1f deg", ImGuiSliderFlags_AlwaysClamp);
    ImGui::PopID();
    if (!changed) return false;
    const float a = glm::radians(azimuth);
    const float e = glm::radians(elevation);
    dir = glm::vec3(std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a));
    return true;
}

void hoverTooltip(const char* text) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text);
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void help(const char* text) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    hoverTooltip(text);
}

}  // namespace dermis::viewer::widgets
