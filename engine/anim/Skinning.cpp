#include "anim/Skinning.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>

namespace dermis {

namespace {

glm::vec3 normalizeOrKeep(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : v;
}

}  // namespace

SkinnedVertices applyMorphTargets(const SkinnedVertices& base, const std::vector<MorphTarget>& targets,
                                  const std::vector<float>& weights) {
    SkinnedVertices out = base;
    const size_t count = std::min(targets.size(), weights.size());
    for (size_t k = 0; k < count; ++k) {
        const float w = weights[k];
        if (w == 0.0f) continue;
        const MorphTarget& t = targets[k];
        for (size_t v = 0; v < out.positions.size() && v < t.positions.size(); ++v) out.positions[v] += w * t.positions[v];
        for (size_t v = 0; v < out.normals.size() && v < t.normals.size(); ++v) out.normals[v] += w * t.normals[v];
        for (size_t v = 0; v < out.tangents.size() && v < t.tangents.size(); ++v)
            out.tangents[v] += glm::vec4(w * t.tangents[v], 0.0f);
    }
    for (glm::vec3& n : out.normals) n = normalizeOrKeep(n);
    for (glm::vec4& t : out.tangents) t = glm::vec4(normalizeOrKeep(glm::vec3(t)), t.w);
    return out;
}

glm::mat4 blendedMatrix(const SkinInfluence& influence, const std::vector<glm::mat4>& joints) {
    glm::mat4 m(0.0f);
    for (int i = 0; i < 4; ++i) {
        const float w = influence.weights[i];
        if (w == 0.0f) continue;
        const size_t j = influence.joints[i];
        m += w * (j < joints.size() ? joints[j] : glm::mat4(1.0f));
    }
    return m;
}

SkinnedVertices skinVertices(const SkinnedVertices& vertices, const std::vector<SkinInfluence>& influences,
                             const std::vector<glm::mat4>& joints) {
    SkinnedVertices out = vertices;
    for (size_t v = 0; v < vertices.positions.size() && v < influences.size(); ++v) {
        const glm::mat4 m = blendedMatrix(influences[v], joints);
        out.positions[v] = glm::vec3(m * glm::vec4(vertices.positions[v], 1.0f));
        const glm::mat3 linear(m);
        if (v < out.normals.size()) out.normals[v] = normalizeOrKeep(glm::inverseTranspose(linear) * vertices.normals[v]);
        if (v < out.tangents.size())
            out.tangents[v] = glm::vec4(normalizeOrKeep(linear * glm::vec3(vertices.tangents[v])), vertices.tangents[v].w);
    }
    return out;
}

}  // namespace dermis
