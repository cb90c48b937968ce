#pragma once
// Where a scene character's animation is at a frame time (scene/Scene.h,
// CharacterAnimation; anim/Rig.h): its clip, its clip time, and its pose.
// The frame plan (plan/FramePlan.h) poses the GPU copy with these; the CPU
// reference poses its copy of the mesh with the same, so that both see the
// character where the frame shows it.

#include "anim/Rig.h"
#include "core/Result.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

namespace dermis {

// The clip the character plays: an index into the rig's clips, or -1 for the
// rest pose (no clips, or clip "none"). An unknown name is an error naming the
// scene, the key and the clips the file has.
Result<int> resolveAnimationClip(const Scene& scene, size_t character, const Rig& rig);

// animation.time_s + animation.speed x frameTimeS, wrapped into the clip when
// looping and clamped otherwise; 0 for the rest pose.
float characterClipTime(const CharacterAnimation& animation, const Rig& rig, int clip, float frameTimeS);

// Deforms the model's mesh (positions, normals, tangents) into the pose the
// character has at frameTimeS; a model without a rig is left as it is.
Status poseModelAt(const Scene& scene, size_t character, float frameTimeS, Model& model);

}  // namespace dermis
