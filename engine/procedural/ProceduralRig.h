#pragma once
// A rig for the procedural head, so that a shipped scene can show an
// animated character without a file: two joints (the neck's foot and the
// skull's base, on the head's mid-plane) and one looping clip, "idle", in
// which the head turns left and right and nods while the neck bends with it.
// Vertices above the skull's base follow the head joint, those at the
// neck's foot the neck joint, and the neck blends between them (smoothstep
// in height), so the skin stretches without tearing.

#include "mesh/Model.h"

#include <glm/glm.hpp>

namespace dermis {

namespace nodding {
inline const glm::vec3 kNeckFootM{0.0f, -0.19f, 0.0f};     // the root joint
inline const glm::vec3 kSkullBaseM{0.0f, -0.075f, -0.005f}; // the head joint, the pivot of the turn and the nod
inline constexpr float kBlendBelowM = 0.045f;  // weights blend from kSkullBaseM.y - this ...
inline constexpr float kBlendAboveM = 0.010f;  // ... to kSkullBaseM.y + this
inline constexpr float kClipDurationS = 4.0f;
}  // namespace nodding

// The head joint's weight of a vertex at height y (metres).
float noddingHeadWeight(float yM);

// Gives `model` (the procedural head) the rig and its "idle" clip; the rest
// pose is the head as made, so frame time 0 of the clip is too.
void addNoddingRig(Model& model);

}  // namespace dermis
