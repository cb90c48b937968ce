#include "pose/CharacterPose.h"

namespace dermis {

Result<int> resolveAnimationClip(const Scene& scene, size_t index, const Rig& rig) {
    const Character& character = scene.characters[index];
    const std::string& name = character.animation.clip;
    if (name == kRestPoseClip || (name.empty() && rig.clips.empty())) return -1;
    if (name.empty()) return 0;
    const int clip = rig.findClip(name);
    if (clip < 0) {
        const std::string source = character.mesh.gltfPath.empty() ? "its mesh" : character.mesh.gltfPath;
        return makeError(scene.path, "/characters/" + std::to_string(index) + "/animation/clip: '" + name +
                                         "' is not a clip of " + source + " (its clips: " + rig.clipList() + ")");
    }
    return clip;
}

float characterClipTime(const CharacterAnimation& animation, const Rig& rig, int clip, float frameTimeS) {
    if (clip < 0 || static_cast<size_t>(clip) >= rig.clips.size()) return 0.0f;
    return clipTime(animation.timeS + animation.speed * frameTimeS, rig.clips[static_cast<size_t>(clip)].durationS(),
                    animation.loop);
}

Status poseModelAt(const Scene& scene, size_t character, float frameTimeS, Model& model) {
    if (model.rig.empty()) return success();
    auto clip = resolveAnimationClip(scene, character, model.rig);
    if (!clip.ok()) return clip.error();
    const float clipTimeS = characterClipTime(scene.characters[character].animation, model.rig, *clip, frameTimeS);
    setVertexFrames(model.mesh, deformRig(model.rig, poseRig(model.rig, *clip, clipTimeS)));
    return success();
}

}  // namespace dermis
