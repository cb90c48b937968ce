// GPU skinning (passes/SkinningPass.cpp, shaders/skinning.comp) against the
// CPU reference (anim/Rig.h deformRig) on the bending cylinder, and the
// frame's skipping: the skin pass and the cached shadow maps rerun only when
// the pose changes.
#include "RenderFixture.h"
#include "TestContent.h"

#include "anim/Rig.h"
#include "anim/Skinning.h"
#include "env/ShTransfer.h"
#include "env/ShTransferCache.h"
#include "gpu/UniformBlocks.h"
#include "import/GltfLoader.h"
#include "mesh/UvLayout.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace dermis;
using namespace dermis::test;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 160;
constexpr int kHeight = 90;
constexpr const char* kSkinPass = "skin:cylinder#0";

class Skinning : public RenderFixture {
protected:
    void SetUp() override {
        RenderFixture::SetUp();
        mDir = fs::temp_directory_path() / ("dermis_skinning_" + std::to_string(::getpid()));
        fs::create_directories(mDir);
        mGltf = (mDir / "bending_cylinder.gltf").string();
        ASSERT_TRUE(writeBendingCylinder(mGltf));
        std::ofstream(mDir / "cylinder.json") << R"({
  "camera": {"position_m": [0.0, 0.12, 0.55], "target_m": [0.03, 0.1, 0.0], "vertical_fov_deg": 35},
  "lights": [{"type": "directional", "direction": [-0.5, -0.4, -0.75], "shadow": true}],
  "characters": [{"name": "cylinder", "mesh": {"gltf": "bending_cylinder.gltf"},
                  "animation": {"clip": "bend"}}]
})";
    }
    void TearDown() override {
        mRenderer.reset();
        std::error_code ignored;
        fs::remove_all(mDir, ignored);
        RenderFixture::TearDown();
    }

    void renderAt(float timeS) {
        FrameRequest request{kWidth, kHeight, Aov::Final};
        request.timeS = timeS;
        const Status status = mRenderer->renderFrame(request);
        ASSERT_TRUE(status.ok()) << status.error().message();
    }
    bool ran(const std::string& pass) const {
        const auto& passes = mRenderer->framePasses();
        return std::find(passes.begin(), passes.end(), pass) != passes.end();
    }
    std::vector<Vertex> gpuVertices() {
        const GpuMesh& mesh = mRenderer->gpuScene().characters()[0].mesh;
        GLint64 bytes = 0;
        glGetNamedBufferParameteri64v(mesh.vertexBuffer.get(), GL_BUFFER_SIZE, &bytes);
        std::vector<Vertex> vertices(static_cast<size_t>(bytes) / sizeof(Vertex));
        glGetNamedBufferSubData(mesh.vertexBuffer.get(), 0, bytes, vertices.data());
        return vertices;
    }

    fs::path mDir;
    std::string mGltf;
};

TEST_F(Skinning, GpuSkinnedVerticesEqualTheCpuReference) {
    load((mDir / "cylinder.json").string());
    auto model = loadGltf(mGltf);
    ASSERT_TRUE(model) << model.error().message();
    for (float timeS : {0.25f, 0.5f, 1.0f, 1.6f}) {
        renderAt(timeS);
        const std::vector<Vertex> gpu = gpuVertices();
        const SkinnedVertices cpu = deformRig(model->rig, poseRig(model->rig, 0, timeS));
        ASSERT_EQ(gpu.size(), cpu.positions.size());
        float position = 0.0f, normal = 0.0f, tangent = 0.0f, uv = 0.0f;
        for (size_t v = 0; v < gpu.size(); ++v) {
            position = std::max(position, glm::length(gpu[v].position - cpu.positions[v]));
            normal = std::max(normal, glm::length(gpu[v].normal - cpu.normals[v]));
            tangent = std::max(tangent, glm::length(glm::vec3(gpu[v].tangent) - glm::vec3(cpu.tangents[v])));
            tangent = std::max(tangent, std::abs(gpu[v].tangent.w - cpu.tangents[v].w));
            uv = std::max(uv, glm::length(gpu[v].uv - model->mesh.vertices[v].uv));
        }
        // The issue's bound, 1e-5 (positions in metres, the cylinder 0.2 m
        // long: 50x float rounding). Weighting only the first joint, or
        // dropping the morph, moves vertices by millimetres and fails it.
        EXPECT_LT(position, 1e-5f) << "t " << timeS;
        EXPECT_LT(normal, 1e-5f) << "t " << timeS;
        EXPECT_LT(tangent, 1e-5f) << "t " << timeS;
        EXPECT_EQ(uv, 0.0f) << "t " << timeS;
    }
}

// The environment's transfer (occlusion "transfer") turns with the skinning
// on the GPU (shaders/transfer_rotate.comp: band 1 as a vector, band 2 as a
// quadratic form R Q R^T) as on the CPU (env/ShTransfer.h rotateTransfer: band
// matrices solved from sample directions), both with the blended matrix's
// polar factor. 1e-4 of the unoccluded T_00 (0.886): float rounding of two
// different computations (measured 2.4e-7). Turning by R^T in the shader fails by 2.1.
TEST_F(Skinning, EnvironmentTransferTurnsWithTheSkinningAsOnTheCpu) {
    load((mDir / "cylinder.json").string(), {R"(environment={"source": "sky"})"});
    auto model = loadGltf(mGltf);
    ASSERT_TRUE(model) << model.error().message();
    renderAt(1.0f);
    ASSERT_TRUE(ran(kSkinPass));
    const GpuEnvironment& environment = mRenderer->gpuEnvironment();
    ASSERT_NE(environment.posedTransfer(0), 0u);
    const size_t count = model->mesh.vertices.size();
    std::vector<ShScalar9> gpu(count);
    glGetNamedBufferSubData(environment.posedTransfer(0), 0, static_cast<GLsizeiptr>(count * sizeof(ShScalar9)), gpu.data());
    // The rest pose's transfer as uploaded (the sky's visible share, env/ShTransfer.h).
    std::vector<ShScalar9> rest(count);
    glGetNamedBufferSubData(environment.restTransfer(0), 0, static_cast<GLsizeiptr>(count * sizeof(ShScalar9)), rest.data());
    const RigPose pose = poseRig(model->rig, 0, 1.0f);
    float worst = 0.0f;
    float turnedMost = 0.0f;
    for (size_t v = 0; v < count; ++v) {
        const glm::mat3 rotation = skinningRotation(blendedMatrix(model->rig.influences[v], pose.palette));
        const ShScalar9 expected = rotateTransfer(rest[v], rotation);
        for (size_t i = 0; i < expected.size(); ++i) {
            worst = std::max(worst, std::abs(gpu[v][i] - expected[i]));
            turnedMost = std::max(turnedMost, std::abs(expected[i] - rest[v][i]));
        }
    }
    std::printf("posed transfer: largest GPU-CPU difference %.2e (the turn changes coefficients by up to %.3f)\n", worst,
                turnedMost);
    EXPECT_GT(turnedMost, 0.1f) << "the tip turns 90 degrees at 1 s";
    EXPECT_LT(worst, 1e-4f);
}

TEST_F(Skinning, SkinAndShadowPassesRerunOnlyWhenThePoseChanges) {
    load((mDir / "cylinder.json").string());
    const std::string shadow = "shadow:light0(dir)";
    renderAt(0.5f);
    EXPECT_TRUE(ran(kSkinPass));
    EXPECT_TRUE(ran(shadow));
    renderAt(0.5f);
    EXPECT_FALSE(ran(kSkinPass)) << "the vertex buffer holds this pose already";
    EXPECT_FALSE(ran(shadow)) << "light and casters unchanged";
    renderAt(0.75f);
    EXPECT_TRUE(ran(kSkinPass));
    EXPECT_TRUE(ran(shadow)) << "the caster moved";
    // speed 0 holds the pose: a later time changes nothing.
    load((mDir / "cylinder.json").string(), {"characters.0.animation.speed=0"});
    renderAt(0.0f);
    renderAt(3.0f);
    EXPECT_FALSE(ran(kSkinPass));
    EXPECT_FALSE(ran(shadow));
}

// The stretch map's derivatives follow the deformation: at 1 s the tip is
// turned 90 degrees, and where the surface moves rigidly (the tip beyond the
// blend and the bulge, every vertex and its neighbours on the "bend" bone
// alone) the GPU's dP/du and dP/dv must equal the derivatives of the
// CPU-deformed mesh worked out afresh from its triangles (mesh/UvLayout.h).
// The rest pose's derivatives, not turned, are off by sqrt(2) of their length.
TEST_F(Skinning, TextureSpaceDerivativesFollowTheDeformation) {
    load((mDir / "cylinder.json").string(), {"mode=ts"});
    auto model = loadGltf(mGltf);
    ASSERT_TRUE(model) << model.error().message();
    renderAt(1.0f);
    ASSERT_TRUE(ran(kSkinPass));
    const GpuRig& rig = mRenderer->gpuScene().characters()[0].rig;
    std::vector<float> gpu(model->mesh.vertices.size() * DERMIS_SKIN_DERIVATIVE_FLOATS);
    glGetNamedBufferSubData(rig.derivatives.get(), 0, static_cast<GLsizeiptr>(gpu.size() * sizeof(float)), gpu.data());

    MeshData deformed = model->mesh;
    const SkinnedVertices cpu = deformRig(model->rig, poseRig(model->rig, 0, 1.0f));
    for (size_t v = 0; v < deformed.vertices.size(); ++v) deformed.vertices[v].position = cpu.positions[v];
    const UvLayout fresh = analyseUvDerivatives(deformed);
    size_t rigid = 0;
    float worst = 0.0f;
    for (size_t v = 0; v < deformed.vertices.size(); ++v) {
        const float restY = model->mesh.vertices[v].position.y;
        const float clearOfBulgeM = BendingCylinder::kJointYM + BendingCylinder::kBulgeHalfWidthM + 0.006f;  // one ring on
        if (restY < clearOfBulgeM || glm::length(fresh.dPdu[v]) == 0.0f) continue;
        const float* d = &gpu[v * DERMIS_SKIN_DERIVATIVE_FLOATS];
        worst = std::max(worst, glm::length(glm::vec3(d[0], d[1], d[2]) - fresh.dPdu[v]) / glm::length(fresh.dPdu[v]));
        worst = std::max(worst, glm::length(glm::vec3(d[3], d[4], d[5]) - fresh.dPdv[v]) / glm::length(fresh.dPdv[v]));
        ++rigid;
    }
    EXPECT_GT(rigid, 400u);
    // Relative float rounding of the two computations: about 1e-6.
    EXPECT_LT(worst, 1e-4f) << "over " << rigid << " rigidly moving vertices";
}

TEST_F(Skinning, CharacterNoPassDrawsIsNotSkinned) {
    // The camera turned away: the cylinder is off screen, and with nothing
    // visible to shade no shadow map keeps it as a caster.
    load((mDir / "cylinder.json").string(), {"camera.target_m=[0,0.12,2]"});
    renderAt(0.5f);
    EXPECT_FALSE(ran(kSkinPass));
    const PassSummary* skin = pass(kSkinPass);
    ASSERT_NE(skin, nullptr);
    EXPECT_NE(skin->culledBecause.find("off screen, and no shadow map redrawn this frame holds it"), std::string::npos)
        << skin->culledBecause;
    // Turned back, it is skinned at once.
    load((mDir / "cylinder.json").string());
    renderAt(0.5f);
    EXPECT_TRUE(ran(kSkinPass));
}

// On llvmpipe a GL_TIME_ELAPSED query holding only a compute dispatch left
// the next pass's query without a start: the shadow pass reported the time
// since boot (hours). FrameServices::dispatchCompute (render/FrameContext.h) works around it; without the
// workaround this test sees over 1e6 ms.
TEST_F(Skinning, PassAfterTheSkinPassHasASaneGpuTime) {
    load((mDir / "cylinder.json").string());
    for (float timeS : {0.1f, 0.2f, 0.3f}) renderAt(timeS);
    const PassSummary* shadow = pass("shadow:light0(dir)");
    ASSERT_NE(shadow, nullptr);
    // A 1024^2 depth map of 2,600 triangles: milliseconds; 10 s leaves room for any machine.
    EXPECT_LT(shadow->gpuMs, 1e4);
    EXPECT_GE(shadow->gpuMs, 0.0);
}

TEST_F(Skinning, UnknownClipIsAnErrorListingTheFilesClips) {
    auto scene = loadScene((mDir / "cylinder.json").string(), {"characters.0.animation.clip=wave"});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    auto renderer = Renderer::create(*scene);
    ASSERT_FALSE(renderer.ok());
    const std::string message = renderer.error().message();
    EXPECT_NE(message.find("cylinder.json: /characters/0/animation/clip: 'wave' is not a clip of"), std::string::npos) << message;
    EXPECT_NE(message.find("(its clips: bend)"), std::string::npos) << message;
}

}  // namespace

// The shipped animated scene (content/scenes/nodding.json): the clip moves
// the image, and its loop brings it back bit for bit at 4 s.
TEST_F(Skinning, NoddingSceneMovesAndLoops) {
    auto at = [&](const char* timeS) {
        load("nodding.json", {std::string("characters.0.animation.time_s=") + timeS});
        return render(Aov::Diffuse, 160, 160);
    };
    const Image start = at("0"), turned = at("1"), looped = at("4");
    ASSERT_EQ(test::countNonFinite(turned), 0u);
    size_t moved = 0, loopDiffers = 0;
    for (size_t i = 0; i < start.texels.size(); ++i) {
        const glm::vec4 d = glm::abs(turned.texels[i] - start.texels[i]);
        if (std::max({d.r, d.g, d.b}) > 0.01f) ++moved;
        if (looped.texels[i] != start.texels[i]) ++loopDiffers;
    }
    std::printf("nodding.json: %zu of %zu pixels change between 0 s and 1 s; %zu differ at 4 s\n", moved,
                start.texels.size(), loopDiffers);
    EXPECT_GT(moved, start.texels.size() / 10);
    EXPECT_EQ(loopDiffers, 0u);
}
