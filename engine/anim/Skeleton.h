#pragma once
// A glTF node hierarchy posed by animation clips, and skins (glTF 2.0 §3.7.3
// "Skins"): a skin's joint matrix j is
//   worldFromJoint(j) x inverseBindMatrix(j)
// which takes a bind-pose vertex (in the glTF scene's space) to its place
// under joint j. The spec's form, inverse(worldFromMeshNode) x that, gives
// the vertex in the mesh node's space, which the mesh node's transform then
// undoes: here the skinned vertex stays in scene space and the mesh node's
// own transform is not applied, as §3.7.3 says it must not be.

#include "anim/Animation.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <string>
#include <vector>

namespace dermis {

struct NodeTransform {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::vec3 scale{1.0f};
    std::vector<float> weights;  // morph target weights of the node's mesh
    // A node given as a matrix (glTF 2.0 §3.5.3 allows either; such a node
    // must not be animated, which the loader checks) keeps it here.
    bool hasFixedMatrix = false;
    glm::mat4 fixedMatrix{1.0f};
    // T x R x S (glTF 2.0 §3.5.3), or the fixed matrix.
    glm::mat4 matrix() const;
};

struct SkeletonNode {
    std::string name;
    int parent = -1;
    NodeTransform rest;  // the node's own TRS when no channel drives it
};

struct Skin {
    std::string name;
    std::vector<int> joints;                      // node indices
    std::vector<glm::mat4> inverseBindMatrices;   // one per joint; identity when the file has none
};

// Local transforms of every node.
using Pose = std::vector<NodeTransform>;

Pose restPose(const std::vector<SkeletonNode>& nodes);

// Overwrites the properties the clip's channels drive at clip time timeS.
// Channels naming a node outside the pose are skipped (the loader refuses them).
void applyClip(const AnimationClip& clip, float timeS, Pose& pose);

// worldFromNode for every node: parent's world x local. Parents may come
// after their children in `nodes`; a cycle is the loader's to refuse.
std::vector<glm::mat4> worldFromNodes(const std::vector<SkeletonNode>& nodes, const Pose& pose);

// worldFromJoint(j) x inverseBindMatrix(j) for every joint of the skin.
std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& worldFromNode);

}  // namespace dermis
