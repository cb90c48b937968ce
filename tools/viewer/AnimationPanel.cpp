// The animation panel: play / pause, the time slider and each animated
// character's clip list (the clips of its glTF, from the renderer's rigs).
#include "viewer/Panels.h"

#include "core/Limits.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace dermis::viewer {
namespace {

// The slider's range: the longest clip any character plays, at least a second.
float longestClipS(const SceneGeometry& geometry) {
    float longest = 1.0f;
    for (size_t c = 0; c < geometry.size(); ++c)
        for (const AnimationClip& clip : geometry.rig(c).clips) longest = std::max(longest, clip.durationS());
    return longest;
}

bool clipCombo(Character& character, const Rig& rig) {
    const std::string current = character.animation.clip.empty() ? "(first clip)" : character.animation.clip;
    bool changed = false;
    if (ImGui::BeginCombo(("clip##" + character.name).c_str(), current.c_str())) {
        std::vector<std::string> names{"", std::string(kRestPoseClip)};
        for (const AnimationClip& clip : rig.clips) names.push_back(clip.name);
        for (const std::string& name : names) {
            const std::string label = name.empty() ? "(first clip)" : name == kRestPoseClip ? "none (rest pose)" : name;
            if (ImGui::Selectable(label.c_str(), name == character.animation.clip)) {
                character.animation.clip = name;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

}  // namespace

bool animationPanel(ViewerState& state, Scene& scene, const SceneGeometry* geometry) {
    if (ImGui::Button(state.playing ? "pause" : "play")) state.playing = !state.playing;
    ImGui::SameLine();
    if (ImGui::Button("0 s")) state.timeS = 0.0f;
    const float longest = geometry ? longestClipS(*geometry) : 1.0f;
    ImGui::SliderFloat("time (s)", &state.timeS, 0.0f, longest, "%.3f");
    ImGui::SliderFloat("playback speed", &state.playbackSpeed, -4.0f, 4.0f, "%.2fx");
    if (!geometry) {
        ImGui::TextDisabled("(clips appear once the scene has rendered)");
        return false;
    }
    bool changed = false;
    bool any = false;
    for (size_t c = 0; c < scene.characters.size() && c < geometry->size(); ++c) {
        const Rig& rig = geometry->rig(c);
        if (rig.empty()) continue;
        any = true;
        Character& character = scene.characters[c];
        ImGui::Separator();
        ImGui::TextUnformatted(character.name.c_str());
        changed |= clipCombo(character, rig);
        changed |= ImGui::SliderFloat(("speed##" + character.name).c_str(), &character.animation.speed, -4.0f, 4.0f, "%.2f");
        changed |= ImGui::Checkbox(("loop##" + character.name).c_str(), &character.animation.loop);
    }
    if (!any) ImGui::TextDisabled("no character of this scene is animated");
    return changed;
}

void advanceAnimationTime(ViewerState& state, float elapsedS) {
    if (!state.playing) return;
    state.timeS += state.playbackSpeed * elapsedS;
    state.timeS = std::clamp(state.timeS, float(-kMaxAnimationTimeS), float(kMaxAnimationTimeS));
}

}  // namespace dermis::viewer
