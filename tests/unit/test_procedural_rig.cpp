// The procedural nodding head (procedural/ProceduralRig.h): its clip is
// documented as a turn of 22 degrees about +Y and a nod of 6 degrees about +X
// at 1 s, about the skull's base, with the neck's foot fixed. The skinning
// chain (node hierarchy, inverse binds, weights) must reproduce that rigid
// motion for every vertex the head joint alone moves.
#include "anim/Rig.h"
#include "procedural/Procedural.h"
#include "procedural/ProceduralRig.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

using namespace dermis;

namespace {

const Model& noddingHead() {
    static const Model model = *makeProceduralModel("nodding_head");
    return model;
}

double largestDistance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(glm::length(a[i] - b[i])));
    return worst;
}

}  // namespace

TEST(ProceduralRig, RestPoseAndClipStartAreTheHeadAsMade) {
    const Model& model = noddingHead();
    const Rig& rig = model.rig;
    ASSERT_EQ(rig.clips.size(), 1u);
    EXPECT_EQ(rig.clips[0].name, "idle");
    EXPECT_FLOAT_EQ(rig.clips[0].durationS(), nodding::kClipDurationS);
    std::vector<glm::vec3> made;
    for (const Vertex& v : model.mesh.vertices) made.push_back(v.position);
    // Float rounding of the joint and inverse-bind products over 0.2 m.
    EXPECT_LT(largestDistance(deformRig(rig, poseRig(rig, -1, 0.0f)).positions, made), 1e-6);
    EXPECT_LT(largestDistance(deformRig(rig, poseRig(rig, 0, 0.0f)).positions, made), 1e-6);
}

TEST(ProceduralRig, HeadTurnsAndNodsAboutTheSkullBaseAndTheNeckFootStays) {
    const Model& model = noddingHead();
    const Rig& rig = model.rig;
    const SkinnedVertices posed = deformRig(rig, poseRig(rig, 0, 1.0f));
    const glm::mat3 turnNod = glm::mat3_cast(glm::angleAxis(glm::radians(22.0f), glm::vec3(0, 1, 0)) *
                                             glm::angleAxis(glm::radians(6.0f), glm::vec3(1, 0, 0)));
    double headWorst = 0.0, headNormalWorst = 0.0, footWorst = 0.0;
    size_t head = 0, foot = 0;
    for (size_t i = 0; i < model.mesh.vertices.size(); ++i) {
        const Vertex& v = model.mesh.vertices[i];
        if (v.position.y > nodding::kSkullBaseM.y + nodding::kBlendAboveM) {
            const glm::vec3 expected = nodding::kSkullBaseM + turnNod * (v.position - nodding::kSkullBaseM);
            headWorst = std::max(headWorst, double(glm::length(posed.positions[i] - expected)));
            headNormalWorst = std::max(headNormalWorst,
                                       double(glm::length(glm::normalize(posed.normals[i]) - turnNod * glm::normalize(v.normal))));
            ++head;
        } else if (v.position.y < nodding::kSkullBaseM.y - nodding::kBlendBelowM) {
            footWorst = std::max(footWorst, double(glm::length(posed.positions[i] - v.position)));
            ++foot;
        }
    }
    std::printf("at 1 s: %zu head vertices off the closed-form turn and nod by %.2e m (normals %.2e), %zu neck vertices "
                "moved by %.2e m\n", head, headWorst, headNormalWorst, foot, footWorst);
    EXPECT_GT(head, 10000u);
    EXPECT_GT(foot, 1000u);
    // Float rounding over 0.2 m; a pivot 1 mm off would move the face by 0.4 mm.
    EXPECT_LT(headWorst, 2e-6);
    EXPECT_LT(headNormalWorst, 1e-5);
    EXPECT_LT(footWorst, 1e-6);
}

TEST(ProceduralRig, WeightsBlendSmoothlyAcrossTheNeck) {
    EXPECT_EQ(noddingHeadWeight(nodding::kSkullBaseM.y - nodding::kBlendBelowM - 0.001f), 0.0f);
    EXPECT_EQ(noddingHeadWeight(nodding::kSkullBaseM.y + nodding::kBlendAboveM + 0.001f), 1.0f);
    float previous = 0.0f;
    for (int i = 0; i <= 100; ++i) {
        const float y = nodding::kSkullBaseM.y - nodding::kBlendBelowM +
                        (nodding::kBlendBelowM + nodding::kBlendAboveM) * float(i) / 100.0f;
        const float w = noddingHeadWeight(y);
        EXPECT_GE(w, previous);
        EXPECT_LE(w - previous, 0.016f);  // smoothstep's largest slope, 1.5 per unit, over 1/100
        previous = w;
    }
}
