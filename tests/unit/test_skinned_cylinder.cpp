// The bending cylinder (tests/support/TestContent.h) through the glTF loader
// and the rig, against closed forms of its construction.
#include "TestContent.h"
#include "anim/Rig.h"
#include "pose/CharacterPose.h"
#include "import/GltfLoader.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <unistd.h>

#include <filesystem>

using namespace dermis;
using test::BendingCylinder;
namespace fs = std::filesystem;

namespace {

class SkinnedCylinder : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        const fs::path dir = fs::temp_directory_path() / ("dermis_cylinder_" + std::to_string(::getpid()));
        fs::create_directories(dir);
        const std::string file = (dir / "bending_cylinder.gltf").string();
        ASSERT_TRUE(test::writeBendingCylinder(file));
        auto model = loadGltf(file);
        ASSERT_TRUE(model) << model.error().message();
        sModel = new Model(std::move(*model));
        fs::remove_all(dir);
    }
    static void TearDownTestSuite() { delete sModel; }

    // Vertex (ring, column) as the construction places it at rest.
    static glm::vec3 restPosition(int ring, int column) {
        const float y = float(ring) / float(BendingCylinder::kRings - 1) * BendingCylinder::kLengthM;
        const float angle = 2.0f * 3.14159265358979f * float(column) / float(BendingCylinder::kSegments);
        return glm::vec3(BendingCylinder::kRadiusM * std::cos(angle), y, -BendingCylinder::kRadiusM * std::sin(angle));
    }
    static size_t index(int ring, int column) { return size_t(ring * (BendingCylinder::kSegments + 1) + column); }

    // The "bend" bone's motion at angle a: a rotation about +Z through the joint.
    static glm::vec3 bent(const glm::vec3& p, float angleDeg) {
        const glm::vec3 pivot(0.0f, BendingCylinder::kJointYM, 0.0f);
        const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(angleDeg), glm::vec3(0, 0, 1));
        return pivot + glm::vec3(r * glm::vec4(p - pivot, 0.0f));
    }

    static Model* sModel;
};
Model* SkinnedCylinder::sModel = nullptr;

TEST_F(SkinnedCylinder, RestPoseIgnoresTheSkinnedMeshNodesTransform) {
    // glTF 2.0 §3.7.3: the skinned mesh node's own translation (5, 5, 5) must not apply.
    const MeshData& mesh = sModel->mesh;
    ASSERT_EQ(mesh.vertices.size(), size_t(BendingCylinder::kRings * (BendingCylinder::kSegments + 1)));
    float worst = 0.0f;
    for (int ring = 0; ring < BendingCylinder::kRings; ++ring)
        for (int column = 0; column <= BendingCylinder::kSegments; ++column)
            worst = std::max(worst, glm::distance(mesh.vertices[index(ring, column)].position, restPosition(ring, column)));
    EXPECT_LT(worst, 1e-6f);
}

TEST_F(SkinnedCylinder, HalfWayThroughTheClipMatchesTheClosedForm) {
    const Rig& rig = sModel->rig;
    ASSERT_EQ(rig.findClip("bend"), 0);
    // LINEAR at 0.5 s: half of kBendDeg by slerp, morph weight 0.5.
    const float angle = 0.5f * BendingCylinder::kBendDeg;
    const RigPose pose = poseRig(rig, 0, 0.5f);
    ASSERT_EQ(pose.morphWeights.size(), 1u);
    EXPECT_NEAR(pose.morphWeights[0], 0.5f, 1e-6f);
    const SkinnedVertices deformed = deformRig(rig, pose);
    const int tip = BendingCylinder::kRings - 1;
    const int joint = (BendingCylinder::kRings - 1) / 2;  // y = kJointYM: weights 0.5 / 0.5, full bulge
    ASSERT_NEAR(restPosition(joint, 0).y, BendingCylinder::kJointYM, 1e-6f);
    float tipError = 0.0f, baseError = 0.0f, jointError = 0.0f;
    for (int column = 0; column <= BendingCylinder::kSegments; ++column) {
        tipError = std::max(tipError, glm::distance(deformed.positions[index(tip, column)], bent(restPosition(tip, column), angle)));
        baseError = std::max(baseError, glm::distance(deformed.positions[index(0, column)], restPosition(0, column)));
        // Morphed first (outwards by 0.5 x kBulgeM), then the average of the two bones' motions.
        glm::vec3 p = restPosition(joint, column);
        const glm::vec3 radial = glm::normalize(glm::vec3(p.x, 0.0f, p.z));
        p += 0.5f * BendingCylinder::kBulgeM * radial;
        jointError = std::max(jointError, glm::distance(deformed.positions[index(joint, column)], 0.5f * p + 0.5f * bent(p, angle)));
    }
    // Float rounding of 0.2 m positions through two matrix products: ~1e-8 m.
    EXPECT_LT(tipError, 1e-6f);
    EXPECT_LT(baseError, 1e-6f);
    EXPECT_LT(jointError, 1e-6f);
    // The tip's normals turn with it.
    const glm::vec3 n = deformed.normals[index(tip, 0)];
    EXPECT_NEAR(glm::distance(n, bent(glm::vec3(1, 0, 0), angle) - bent(glm::vec3(0), angle)), 0.0f, 1e-6f);
}

// What the CPU reference renders (pose/CharacterPose.h): the character
// posed as the frame shows it. time_s 0.5 at speed 2 and frame time 0.25 s
// is clip time 1 s, the full 90-degree bend.
TEST_F(SkinnedCylinder, CpuCopyIsPosedAtTheFramesClipTime) {
    Scene scene;
    scene.path = "scene.json";
    Character character;
    character.animation.clip = "bend";
    character.animation.timeS = 0.5f;
    character.animation.speed = 2.0f;
    scene.characters.push_back(character);
    Model model = *sModel;
    ASSERT_TRUE(poseModelAt(scene, 0, 0.25f, model).ok());
    const int tip = BendingCylinder::kRings - 1;
    float worst = 0.0f;
    for (int column = 0; column <= BendingCylinder::kSegments; ++column)
        worst = std::max(worst, glm::distance(model.mesh.vertices[index(tip, column)].position,
                                              bent(restPosition(tip, column), BendingCylinder::kBendDeg)));
    EXPECT_LT(worst, 1e-6f);
    // An unknown clip is the scene's error, as the renderer gives it.
    scene.characters[0].animation.clip = "wave";
    const Status unknown = poseModelAt(scene, 0, 0.0f, model);
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message().find("scene.json: /characters/0/animation/clip: 'wave' is not a clip"), std::string::npos)
        << unknown.error().message();
}

TEST_F(SkinnedCylinder, PoseBoundsHoldEveryVertexAtEveryTime) {
    const Rig& rig = sModel->rig;
    for (float t = 0.0f; t <= 2.0f; t += 0.125f) {
        const RigPose pose = poseRig(rig, 0, t);
        glm::vec3 lo, hi;
        rigPoseBounds(rig, pose, lo, hi);
        const SkinnedVertices deformed = deformRig(rig, pose);
        glm::vec3 actualLo(INFINITY), actualHi(-INFINITY);
        for (const glm::vec3& p : deformed.positions) {
            actualLo = glm::min(actualLo, p);
            actualHi = glm::max(actualHi, p);
        }
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(lo[a], actualLo[a] + 1e-6f) << "t " << t;
            EXPECT_GE(hi[a], actualHi[a] - 1e-6f) << "t " << t;
            // Conservative, not loose: at most a bone's box diagonal larger (each bone's box turns whole).
            EXPECT_LT(actualLo[a] - lo[a], 0.15f) << "t " << t;
            EXPECT_LT(hi[a] - actualHi[a], 0.15f) << "t " << t;
        }
    }
}

}  // namespace
