#include "anim/Rig.h"

#include <algorithm>
#include <cmath>

namespace dermis {

int Rig::findClip(const std::string& name) const {
    for (size_t c = 0; c < clips.size(); ++c)
        if (clips[c].name == name) return static_cast<int>(c);
    return -1;
}

std::string Rig::clipList() const {
    std::string list;
    for (const AnimationClip& clip : clips) list += (list.empty() ? "" : ", ") + clip.name;
    return list.empty() ? "none" : list;
}

void Rig::computeEntryBounds() {
    const size_t entries = palette.size();
    entryMin.assign(entries, glm::vec3(INFINITY));
    entryMax.assign(entries, glm::vec3(-INFINITY));
    entryMorphReach.assign(entries, std::vector<glm::vec3>(morphSlots.size(), glm::vec3(0.0f)));
    for (size_t v = 0; v < bind.positions.size() && v < influences.size(); ++v) {
        for (int i = 0; i < 4; ++i) {
            const size_t entry = influences[v].joints[i];
            if (influences[v].weights[i] == 0.0f || entry >= entries) continue;
            entryMin[entry] = glm::min(entryMin[entry], bind.positions[v]);
            entryMax[entry] = glm::max(entryMax[entry], bind.positions[v]);
            for (size_t s = 0; s < morphSlots.size(); ++s) {
                if (v < morphTargets[s].positions.size())
                    entryMorphReach[entry][s] = glm::max(entryMorphReach[entry][s], glm::abs(morphTargets[s].positions[v]));
            }
        }
    }
}

RigPose poseRig(const Rig& rig, int clip, float clipTimeS) {
    Pose pose = restPose(rig.nodes);
    if (clip >= 0 && static_cast<size_t>(clip) < rig.clips.size()) applyClip(rig.clips[static_cast<size_t>(clip)], clipTimeS, pose);
    const std::vector<glm::mat4> world = worldFromNodes(rig.nodes, pose);
    std::vector<std::vector<glm::mat4>> joints;
    for (const Skin& skin : rig.skins) joints.push_back(jointMatrices(skin, world));
    RigPose out;
    out.palette.reserve(rig.palette.size());
    for (const PaletteEntry& entry : rig.palette) {
        out.palette.push_back(entry.skin >= 0 ? joints[static_cast<size_t>(entry.skin)][static_cast<size_t>(entry.joint)]
                                              : world[static_cast<size_t>(entry.node)]);
    }
    for (const MorphSlot& slot : rig.morphSlots) {
        const std::vector<float>& weights = pose[static_cast<size_t>(slot.node)].weights;
        out.morphWeights.push_back(static_cast<size_t>(slot.target) < weights.size() ? weights[static_cast<size_t>(slot.target)]
                                                                                    : 0.0f);
    }
    return out;
}

SkinnedVertices deformRig(const Rig& rig, const RigPose& pose) {
    return skinVertices(applyMorphTargets(rig.bind, rig.morphTargets, pose.morphWeights), rig.influences, pose.palette);
}

void rigPoseBounds(const Rig& rig, const RigPose& pose, glm::vec3& min, glm::vec3& max) {
    min = glm::vec3(INFINITY);
    max = glm::vec3(-INFINITY);
    for (size_t e = 0; e < rig.palette.size() && e < rig.entryMin.size(); ++e) {
        if (rig.entryMin[e].x > rig.entryMax[e].x) continue;  // moves no vertex
        glm::vec3 reach(0.0f);
        for (size_t s = 0; s < pose.morphWeights.size() && s < rig.entryMorphReach[e].size(); ++s)
            reach += std::abs(pose.morphWeights[s]) * rig.entryMorphReach[e][s];
        const glm::vec3 lo = rig.entryMin[e] - reach, hi = rig.entryMax[e] + reach;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
            const glm::vec3 w = glm::vec3(pose.palette[e] * glm::vec4(p, 1.0f));
            min = glm::min(min, w);
            max = glm::max(max, w);
        }
    }
}

}  // namespace dermis
