// Back-face culling's two conditions (mesh/MeshTopology.h, plan/BackFaceCulling.h):
// which meshes are closed and wound outward, and when the view lets the
// G-buffer cull them. No GL.
#include "TestSupport.h"
#include "import/GltfLoader.h"
#include "mesh/MeshTopology.h"
#include "procedural/Procedural.h"
#include "procedural/ProceduralShapes.h"
#include "plan/BackFaceCulling.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <filesystem>

using namespace dermis;

namespace {

MeshData flipped(MeshData mesh) {
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    return mesh;
}

// Two copies of a mesh, the second moved by `offset` (vertices and indices appended).
MeshData withCopy(const MeshData& mesh, glm::vec3 offset) {
    MeshData out = mesh;
    const auto base = static_cast<uint32_t>(mesh.vertices.size());
    for (Vertex v : mesh.vertices) {
        v.position += offset;
        out.vertices.push_back(v);
    }
    for (uint32_t i : mesh.indices) out.indices.push_back(base + i);
    return out;
}

}  // namespace

TEST(MeshTopology, ClosedOutwardMeshesAndTheOnesThatAreNot) {
    const MeshData sphere = makeSphereMesh();  // seam column and poles duplicated
    EXPECT_TRUE(isClosedOutward(sphere));
    EXPECT_TRUE(isClosedOutward(makeWedgeMesh()));  // flat-shaded: vertices split per face
    EXPECT_FALSE(isClosedOutward(flipped(sphere)));  // wound inward: negative volume
    EXPECT_FALSE(isClosedOutward(makePlaneMesh()));  // open
    MeshData holed = sphere;
    holed.indices.resize(holed.indices.size() - 3);  // one triangle gone: its three edges lose their twins
    EXPECT_FALSE(isClosedOutward(holed));
    MeshData doubled = sphere;
    doubled.indices.insert(doubled.indices.end(), sphere.indices.begin(), sphere.indices.begin() + 3);
    EXPECT_FALSE(isClosedOutward(doubled));  // an edge used twice one way
    // Two intersecting closed parts: each hides its own back faces.
    EXPECT_TRUE(isClosedOutward(withCopy(sphere, glm::vec3(0.05f, 0.0f, 0.0f))));
    EXPECT_FALSE(isClosedOutward(MeshData{}));
    // The procedural head (with its ears) is closed: the G-buffer culls its back faces.
    auto head = makeProceduralModel("head");
    ASSERT_TRUE(head.ok());
    EXPECT_TRUE(isClosedOutward(head->mesh));
}

// ctest: content
TEST(MeshTopology, TheScanIsClosed) {
    const std::filesystem::path file = std::filesystem::path(test::sharedContentDir()) / "LeePerrySmith" / "LeePerrySmith.glb";
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "shared content not found: " << file << "; skipping";
    auto scan = loadGltf(file.string());
    ASSERT_TRUE(scan.ok()) << scan.error().message();
    EXPECT_TRUE(isClosedOutward(scan->mesh));  // measured: closed at the neck too, so the G-buffer culls it
}

TEST(BackFaceCulling, OnlyForStaticClosedMeshesWhollyBeyondTheNearPlane) {
    ViewParams view;
    view.viewFromWorld = glm::lookAt(glm::vec3(0, 0, 1), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));  // eye at z = 1
    view.nearM = 0.05f;
    CharacterPlacement head;
    head.worldBounds = Bounds{glm::vec3(-0.1f), glm::vec3(0.1f)};  // nearest face 0.9 m from the eye
    EXPECT_TRUE(mayCullBackFaces(true, head, view));
    EXPECT_FALSE(mayCullBackFaces(false, head, view));  // open mesh
    CharacterPlacement animated = head;
    animated.animated = true;
    EXPECT_FALSE(mayCullBackFaces(true, animated, view));
    CharacterPlacement mirrored = head;
    mirrored.worldFromObject = glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f));  // flips the winding
    EXPECT_FALSE(mayCullBackFaces(true, mirrored, view));
    CharacterPlacement cut = head;
    cut.worldBounds.max.z = 0.96f;  // 4 cm from the eye: the near plane (5 cm) cuts into the box
    EXPECT_FALSE(mayCullBackFaces(true, cut, view));
    cut.worldBounds.max.z = 0.94f;  // 6 cm: wholly beyond it
    EXPECT_TRUE(mayCullBackFaces(true, cut, view));
    CharacterPlacement around = head;
    around.worldBounds = Bounds{glm::vec3(-2.0f), glm::vec3(2.0f)};  // the eye inside the box
    EXPECT_FALSE(mayCullBackFaces(true, around, view));
    CharacterPlacement behind = head;
    behind.worldBounds = Bounds{glm::vec3(-0.1f, -0.1f, 1.5f), glm::vec3(0.1f, 0.1f, 1.7f)};  // behind the eye
    EXPECT_FALSE(mayCullBackFaces(true, behind, view));
}
