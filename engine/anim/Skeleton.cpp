#include "anim/Skeleton.h"

#include <glm/gtc/matrix_transform.hpp>

namespace dermis {

glm::mat4 NodeTransform::matrix() const {
    if (hasFixedMatrix) return fixedMatrix;
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) * glm::scale(glm::mat4(1.0f), scale);
}

Pose restPose(const std::vector<SkeletonNode>& nodes) {
    Pose pose;
    pose.reserve(nodes.size());
    for (const SkeletonNode& node : nodes) pose.push_back(node.rest);
    return pose;
}

void applyClip(const AnimationClip& clip, float timeS, Pose& pose) {
    float value[4];
    for (const AnimationChannel& channel : clip.channels) {
        if (channel.node < 0 || size_t(channel.node) >= pose.size()) continue;
        NodeTransform& node = pose[size_t(channel.node)];
        switch (channel.property) {
        case AnimatedProperty::Translation:
            sampleChannel(channel, timeS, value);
            node.translation = glm::vec3(value[0], value[1], value[2]);
            break;
        case AnimatedProperty::Rotation:
            sampleChannel(channel, timeS, value);
            node.rotation = glm::quat(value[3], value[0], value[1], value[2]);
            break;
        case AnimatedProperty::Scale:
            sampleChannel(channel, timeS, value);
            node.scale = glm::vec3(value[0], value[1], value[2]);
            break;
        case AnimatedProperty::Weights:
            node.weights.resize(size_t(channel.components));
            sampleChannel(channel, timeS, node.weights.data());
            break;
        }
    }
}

std::vector<glm::mat4> worldFromNodes(const std::vector<SkeletonNode>& nodes, const Pose& pose) {
    const size_t n = nodes.size();
    std::vector<glm::mat4> world(n);
    std::vector<char> done(n, 0);
    std::vector<size_t> chain;
    for (size_t start = 0; start < n; ++start) {
        // Walk up to the first node already done (or a root), then back down.
        chain.clear();
        for (size_t node = start; !done[node]; ) {
            chain.push_back(node);
            const int parent = nodes[node].parent;
            if (parent < 0 || size_t(parent) >= n || chain.size() > n) break;
            node = size_t(parent);
        }
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const size_t node = *it;
            const int parent = nodes[node].parent;
            const glm::mat4 local = pose[node].matrix();
            world[node] = parent >= 0 && size_t(parent) < n && done[size_t(parent)] ? world[size_t(parent)] * local : local;
            done[node] = 1;
        }
    }
    return world;
}

std::vector<glm::mat4> jointMatrices(const Skin& skin, const std::vector<glm::mat4>& worldFromNode) {
    std::vector<glm::mat4> matrices(skin.joints.size(), glm::mat4(1.0f));
    for (size_t j = 0; j < skin.joints.size(); ++j) {
        const int node = skin.joints[j];
        if (node < 0 || size_t(node) >= worldFromNode.size()) continue;
        const glm::mat4 inverseBind = j < skin.inverseBindMatrices.size() ? skin.inverseBindMatrices[j] : glm::mat4(1.0f);
        matrices[j] = worldFromNode[size_t(node)] * inverseBind;
    }
    return matrices;
}

}  // namespace dermis
