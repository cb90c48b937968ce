#pragma once
// Morph targets and linear-blend skinning on the CPU (glTF 2.0 §3.7.2.2
// "Morph Targets" and §3.7.3 "Skins"): the reference the GPU skinning is
// tested against, and what bind-pose tools use.
//
//   morphed = base + sum_k w_k delta_k          (positions, normals, tangents)
//   skinned = (sum_i w_i J[joint_i]) x morphed  (w: the vertex's 4 weights)
//
// Normals are transformed by the inverse transpose of the blended matrix and
// renormalised; tangents by the blended matrix and renormalised, keeping w.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace dermis {

// A vertex's four joint influences (glTF JOINTS_0 / WEIGHTS_0).
struct SkinInfluence {
    glm::u16vec4 joints{0};
    glm::vec4 weights{0.0f};
};

// One morph target's per-vertex displacements; a missing attribute is empty.
struct MorphTarget {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> tangents;
};

struct SkinnedVertices {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec4> tangents;  // xyz, w the bitangent sign
};

// base + the weighted targets (weights beyond the target count are ignored).
SkinnedVertices applyMorphTargets(const SkinnedVertices& base, const std::vector<MorphTarget>& targets,
                                  const std::vector<float>& weights);

// The blended matrix of one vertex. Joint indices outside `joints` count as
// identity (the loader refuses them in files).
glm::mat4 blendedMatrix(const SkinInfluence& influence, const std::vector<glm::mat4>& joints);

SkinnedVertices skinVertices(const SkinnedVertices& vertices, const std::vector<SkinInfluence>& influences,
                             const std::vector<glm::mat4>& joints);

}  // namespace dermis
