#pragma once
// Everything that moves a model's vertices, as a loader leaves it: the node
// hierarchy, skins, clips and morph targets of a glTF file, and per vertex
// which matrices of one shared palette move it.
//
// The palette unifies the two ways glTF moves a mesh (glTF 2.0 §3.7.3 and
// §3.5.3): a skinned primitive's vertices blend up to four joint matrices
// (worldFromJoint x inverseBindMatrix), and a primitive of an unskinned mesh
// node follows its node rigidly (one entry, worldFromNode, weight 1). The
// vertices the palette applies to (bindPositions, ...) are the file's own,
// before any node transform; morph targets (§3.7.2.2) displace them first:
//
//   morphed  = bind + sum_s w_s delta_s          (s: a morph slot, one per
//                                                 target of each mesh node)
//   deformed = (sum_i w_i palette[joint_i]) x morphed
//
// GPU skinning (shaders/skinning.comp) evaluates exactly this; deformRig is
// its CPU reference.

#include "anim/Skeleton.h"
#include "anim/Skinning.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace dermis {

// Limits of what the GPU skinning takes (shaders/include/UniformBlocks.glsl
// keeps none of its own: the palette and weights are SSBOs sized by these).
inline constexpr size_t kMaxPaletteEntries = 4096;    // joint indices are 16-bit
inline constexpr size_t kMaxMorphSlots = 256;
inline constexpr size_t kMaxMorphDeltas = size_t(1) << 25;  // slots x vertices, 384 MiB of vec3 at most

struct PaletteEntry {
    int node = -1;  // the joint's or the rigid mesh node's index
    int skin = -1;  // the skin it is a joint of; -1 for a rigid mesh node
    int joint = 0;  // index into the skin's joints
};

struct MorphSlot {
    int node = -1;    // the mesh node whose weights drive it
    int target = 0;   // which of that mesh's targets
};

struct Rig {
    std::vector<SkeletonNode> nodes;
    std::vector<Skin> skins;
    std::vector<AnimationClip> clips;
    std::vector<PaletteEntry> palette;
    std::vector<MorphSlot> morphSlots;
    // Per vertex of the model's mesh, in its order.
    SkinnedVertices bind;
    std::vector<SkinInfluence> influences;
    std::vector<MorphTarget> morphTargets;  // one per slot; every attribute either empty or one per vertex
    // Per palette entry: the box of the bind positions it moves with a
    // non-zero weight, and per slot the largest |delta| among them (what
    // bounds() needs to bound every pose without deforming it).
    std::vector<glm::vec3> entryMin, entryMax;
    std::vector<std::vector<glm::vec3>> entryMorphReach;  // [entry][slot]

    bool empty() const { return palette.empty(); }
    // The clip named `name`, or -1.
    int findClip(const std::string& name) const;
    // "Idle, Run, Walk" (or "none").
    std::string clipList() const;
    // Fills entryMin/entryMax/entryMorphReach from bind, influences and morphTargets.
    void computeEntryBounds();
};

struct RigPose {
    std::vector<glm::mat4> palette;  // one per Rig::palette entry
    std::vector<float> morphWeights; // one per Rig::morphSlots entry
};

// The pose at clipTimeS into clip `clip` (-1: the rest pose).
RigPose poseRig(const Rig& rig, int clip, float clipTimeS);

// Morphs then skins the bind vertices (the CPU reference of the GPU skinning).
SkinnedVertices deformRig(const Rig& rig, const RigPose& pose);

// A box holding every deformed vertex of this pose: each vertex is a convex
// combination (weights >= 0, summing to one) of its entries' matrices applied
// to its morphed position, and its morphed position lies in its entries'
// boxes grown by sum_s |w_s| x reach; so the union of the grown boxes, each
// transformed by its matrix, holds it.
void rigPoseBounds(const Rig& rig, const RigPose& pose, glm::vec3& min, glm::vec3& max);

}  // namespace dermis
