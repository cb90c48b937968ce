#include "viewer/Overlay.h"

#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <string>

namespace dermis::viewer {
namespace {

const ImU32 kTextColour = IM_COL32(240, 240, 240, 255);
const ImU32 kLabelBackground = IM_COL32(0, 0, 0, 160);
const ImU32 kErrorColour = IM_COL32(255, 110, 90, 255);
const ImU32 kOkColour = IM_COL32(140, 230, 140, 255);
constexpr float kPad = 6.0f;
constexpr std::chrono::seconds kMessageShown{6};

void label(ImDrawList* list, ImVec2 at, const std::string& text, ImU32 colour = kTextColour) {
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    list->AddRectFilled(ImVec2(at.x - kPad * 0.5f, at.y - kPad * 0.5f),
                        ImVec2(at.x + size.x + kPad * 0.5f, at.y + size.y + kPad * 0.5f), kLabelBackground, 3.0f);
    list->AddText(at, colour, text.c_str());
}

std::string describeB(const std::vector<SceneDifference>& differences) {
    if (differences.empty()) return "B (same as A)";
    std::string text = "B: " + differences[0].key + " = " + differences[0].b;
    if (differences.size() > 1) text += " (+" + std::to_string(differences.size() - 1) + " more)";
    return text;
}

// The difference view's colour scale, matching SplitView's false colours.
void colourScale(ImDrawList* list, const UiRect& area, float scale) {
    static const ImU32 kStops[6] = {IM_COL32(0, 0, 0, 255),     IM_COL32(26, 26, 204, 255),  IM_COL32(0, 179, 204, 255),
                                    IM_COL32(51, 204, 26, 255), IM_COL32(255, 217, 0, 255), IM_COL32(255, 26, 0, 255)};
    const float width = 200.0f;
    const float height = 10.0f;
    const ImVec2 origin(area.x + kPad * 2.0f, area.y + area.height - height - 3.0f * ImGui::GetTextLineHeight() - 4.0f * kPad);
    for (int i = 0; i < 5; ++i) {
        const float x0 = origin.x + width * static_cast<float>(i) / 5.0f;
        const float x1 = origin.x + width * static_cast<float>(i + 1) / 5.0f;
        list->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), kStops[i], kStops[i + 1],
                                      kStops[i + 1], kStops[i]);
    }
    char text[64];
    std::snprintf(text, sizeof text, "0 .. %.3g", 1.0 / static_cast<double>(scale));
    label(list, ImVec2(origin.x, origin.y + height + kPad), std::string("|A - B|  ") + text);
}

}  // namespace

void drawOverlay(const UiRect& area, const ViewerState& state, const std::vector<SceneDifference>& differences) {
    if (area.width <= 0.0f || area.height <= 0.0f) return;
    ImDrawList* list = ImGui::GetBackgroundDrawList();
    const float line = ImGui::GetTextLineHeight() + kPad * 2.0f;
    // Labels go along the bottom edge: the profiler sits at the top right.
    const float bottom = area.y + area.height - line;
    if (state.mode == ViewMode::Split) {
        const float x = area.x + state.dividerFraction * area.width;
        list->AddLine(ImVec2(x, area.y), ImVec2(x, area.y + area.height), IM_COL32(255, 255, 255, 200), 2.0f);
        list->AddCircleFilled(ImVec2(x, area.y + area.height * 0.5f), 6.0f, IM_COL32(255, 255, 255, 220));
        const ImVec2 aSize = ImGui::CalcTextSize("A");
        label(list, ImVec2(x - aSize.x - kPad * 2.0f, bottom), "A");
        label(list, ImVec2(x + kPad * 2.0f, bottom), describeB(differences));
    } else if (state.mode == ViewMode::Difference) {
        label(list, ImVec2(area.x + kPad * 2.0f, bottom), "difference A - B; " + describeB(differences));
        colourScale(list, area, state.differenceScale);
    }
    // Errors and the latest message stack at the top left; a message fades after a few seconds.
    float top = area.y + kPad * 2.0f;
    if (!state.renderError.empty()) {
        label(list, ImVec2(area.x + kPad * 2.0f, top), "render error: " + state.renderError, kErrorColour);
        top += line;
    }
    if (!state.message.empty() && std::chrono::steady_clock::now() - state.messageTime < kMessageShown) {
        label(list, ImVec2(area.x + kPad * 2.0f, top), state.message, state.messageIsError ? kErrorColour : kOkColour);
    }
}

}  // namespace dermis::viewer
