#include "viewer/ProfilerPanel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace dermis::viewer {
namespace {

const ImVec4 kCulledColour{0.55f, 0.55f, 0.55f, 1.0f};
constexpr float kGraphWidth = 64.0f;

void frameTotal(const PassHistory& history) {
    const SampleRing& total = history.frameGpuHistory();
    char overlay[80];
    std::snprintf(overlay, sizeof overlay, "frame %.2f ms, avg %.2f", static_cast<double>(total.latest()),
                  static_cast<double>(total.mean()));
    const float top = std::max(total.max() * 1.1f, 0.01f);
    ImGui::PlotLines("##frame", total.data(), total.size(), total.offset(), overlay, 0.0f, top,
                     ImVec2(ImGui::GetContentRegionAvail().x, 34.0f));
}

void passRow(const PassTrack& track, float rowHeight) {
    ImGui::PushID(track.name.c_str());
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (track.executed) {
        ImGui::TextUnformatted(track.name.c_str());
    } else {
        ImGui::TextColored(kCulledColour, "%s", track.name.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("culled: %s", track.culledBecause.c_str());
    }
    ImGui::TableNextColumn();
    if (track.executed) {
        ImGui::Text("%6.2f", static_cast<double>(track.gpuMs.latest()));
    } else {
        ImGui::TextColored(kCulledColour, "culled");
    }
    ImGui::TableNextColumn();
    ImGui::Text("%6.2f", static_cast<double>(track.gpuMs.mean()));
    ImGui::TableNextColumn();
    const float top = std::max(track.gpuMs.max() * 1.1f, 0.01f);
    ImGui::PlotLines("##gpu", track.gpuMs.data(), track.gpuMs.size(), track.gpuMs.offset(), nullptr, 0.0f, top,
                     ImVec2(kGraphWidth, rowHeight));
    ImGui::TableNextColumn();
    ImGui::Text("%5.2f", static_cast<double>(track.cpuMs.latest()));
    ImGui::PopID();
}

void passTable(const PassHistory& history) {
    frameTotal(history);
    ImGui::BeginChild("scroll");
    const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
    const std::vector<const PassTrack*> passes = history.passes();
    if (ImGui::BeginTable("passes", 5, flags)) {
        // The numbers' widths up front: fitted to their content, the columns
        // were one letter wide until the first timings arrived.
        const float numberWidth = ImGui::CalcTextSize("0000.00").x;
        ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("GPU", ImGuiTableColumnFlags_WidthFixed, numberWidth);
        ImGui::TableSetupColumn("avg", ImGuiTableColumnFlags_WidthFixed, numberWidth);
        ImGui::TableSetupColumn("history", ImGuiTableColumnFlags_WidthFixed, kGraphWidth);
        ImGui::TableSetupColumn("CPU", ImGuiTableColumnFlags_WidthFixed, numberWidth);
        ImGui::TableHeadersRow();
        const float rowHeight = ImGui::GetTextLineHeight();
        for (const PassTrack* track : passes) passRow(*track, rowHeight);
        ImGui::EndTable();
    }
    // Why each culled pass was culled, in full (a table cell would clip it).
    ImGui::PushTextWrapPos(0.0f);
    for (const PassTrack* track : passes) {
        if (track->executed || track->culledBecause.empty()) continue;
        ImGui::TextColored(kCulledColour, "%s culled: %s", track->name.c_str(), track->culledBecause.c_str());
    }
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
}

}  // namespace

void profilerPanel(const std::vector<ProfiledSide>& sides, const std::string& renderer, int width, int height,
                   double wallMs, bool& clearRequested) {
    ImGui::TextDisabled("%s, %dx%d", renderer.c_str(), width, height);
    ImGui::Text("viewer %.0f ms/frame (%.1f fps)", wallMs, wallMs > 0.0 ? 1000.0 / wallMs : 0.0);
    for (const ProfiledSide& side : sides) {
        ImGui::SameLine();
        ImGui::Text(" %s %.1f", side.label, static_cast<double>(side.history->frameGpuMs()));
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("clear")) clearRequested = true;
    if (sides.size() == 1) {
        passTable(*sides[0].history);
        return;
    }
    if (ImGui::BeginTabBar("sides")) {
        for (const ProfiledSide& side : sides) {
            if (ImGui::BeginTabItem(side.label)) {
                passTable(*side.history);
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
    }
}

}  // namespace dermis::viewer
