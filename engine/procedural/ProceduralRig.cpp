#include "procedural/ProceduralRig.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>

namespace dermis {

float noddingHeadWeight(float yM) {
    const float a = nodding::kSkullBaseM.y - nodding::kBlendBelowM;
    const float b = nodding::kSkullBaseM.y + nodding::kBlendAboveM;
    const float t = std::clamp((yM - a) / (b - a), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

namespace {

// The head's rotation at each second of the clip: a turn about +Y and a nod about +X (degrees).
struct Key {
    float timeS, turnDeg, nodDeg;
};
constexpr Key kHeadKeys[] = {{0.0f, 0.0f, 0.0f}, {1.0f, 22.0f, 6.0f}, {2.0f, 0.0f, -8.0f}, {3.0f, -22.0f, 6.0f},
                             {4.0f, 0.0f, 0.0f}};

glm::quat headRotation(const Key& key) {
    return glm::angleAxis(glm::radians(key.turnDeg), glm::vec3(0, 1, 0)) *
           glm::angleAxis(glm::radians(key.nodDeg), glm::vec3(1, 0, 0));
}

}  // namespace

void addNoddingRig(Model& model) {
    Rig& rig = model.rig;
    SkeletonNode neck;
    neck.name = "neck";
    neck.rest.translation = nodding::kNeckFootM;
    SkeletonNode head;
    head.name = "head";
    head.parent = 0;
    head.rest.translation = nodding::kSkullBaseM - nodding::kNeckFootM;
    rig.nodes = {neck, head};
    Skin skin;
    skin.name = "nodding";
    skin.joints = {0, 1};
    skin.inverseBindMatrices = {glm::translate(glm::mat4(1.0f), -nodding::kNeckFootM),
                                glm::translate(glm::mat4(1.0f), -nodding::kSkullBaseM)};
    rig.skins = {skin};
    rig.palette = {{0, 0, 0}, {1, 0, 1}};

    AnimationClip clip;
    clip.name = "idle";
    AnimationChannel rotation;
    rotation.node = 1;
    rotation.property = AnimatedProperty::Rotation;
    rotation.components = 4;
    for (const Key& key : kHeadKeys) {
        const glm::quat q = headRotation(key);
        rotation.timesS.push_back(key.timeS);
        rotation.values.insert(rotation.values.end(), {q.x, q.y, q.z, q.w});
    }
    clip.channels.push_back(rotation);
    rig.clips = {clip};

    for (const Vertex& v : model.mesh.vertices) {
        const float w = noddingHeadWeight(v.position.y);
        SkinInfluence influence;
        influence.joints = glm::u16vec4(0, 1, 0, 0);
        influence.weights = glm::vec4(1.0f - w, w, 0.0f, 0.0f);
        rig.influences.push_back(influence);
        rig.bind.positions.push_back(v.position);
        rig.bind.normals.push_back(v.normal);
        rig.bind.tangents.push_back(v.tangent);
    }
    rig.computeEntryBounds();
}

}  // namespace dermis
