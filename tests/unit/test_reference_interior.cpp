// Surface inside the body (reference/SurfaceInterior.h; docs/reference.md,
// "Surface inside the body"): where closed parts of one mesh pass into one
// another, the surface of each inside the other gives no light to the
// subsurface integral.
#include "ReferenceTestScenes.h"

#include "reference/CharacterSurface.h"
#include "reference/ReferenceRenderer.h"
#include "reference/SurfaceInterior.h"

#include <gtest/gtest.h>

#include <array>

using namespace dermis;
using namespace dermis::test;

namespace {

// An axis-aligned box as six quads, counter-clockwise seen from outside, each
// face with its own four vertices (as a flat-shaded mesh has them); without
// `withTop`, the +Y face is left out and the box is open.
void appendBox(MeshData& mesh, const glm::vec3& lo, const glm::vec3& hi, bool withTop = true) {
    const std::array<glm::vec3, 8> c = {glm::vec3(lo.x, lo.y, lo.z), glm::vec3(hi.x, lo.y, lo.z), glm::vec3(hi.x, hi.y, lo.z),
                                        glm::vec3(lo.x, hi.y, lo.z), glm::vec3(lo.x, lo.y, hi.z), glm::vec3(hi.x, lo.y, hi.z),
                                        glm::vec3(hi.x, hi.y, hi.z), glm::vec3(lo.x, hi.y, hi.z)};
    const std::array<std::array<int, 4>, 6> faces = {{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3},
                                                      {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}}};
    for (size_t f = 0; f < faces.size(); ++f) {
        if (!withTop && f == 5) continue;
        const auto& q = faces[f];
        const glm::vec3 normal = glm::normalize(glm::cross(c[q[1]] - c[q[0]], c[q[2]] - c[q[0]]));
        const auto first = uint32_t(mesh.vertices.size());
        for (int k : q) {
            Vertex v;
            v.position = c[size_t(k)];
            v.normal = normal;
            mesh.vertices.push_back(v);
        }
        mesh.indices.insert(mesh.indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
}

Model twoBoxes(const glm::vec3& innerLo, const glm::vec3& innerHi, bool outerClosed = true) {
    Model model;
    // The outer box's top face is the y = 0 plane that downAt() looks at.
    appendBox(model.mesh, glm::vec3(-0.1f, -0.04f, -0.1f), glm::vec3(0.1f, 0.0f, 0.1f), outerClosed);
    appendBox(model.mesh, innerLo, innerHi);
    return model;
}

// The first triangle whose three corners all lie at height y and whose normal points along `normalY`.
size_t triangleAtHeight(const reference::CharacterSurface& surface, float y, float normalY, size_t from = 0) {
    for (size_t t = from; t < surface.triangleCount(); ++t) {
        const glm::vec3 a = surface.corner(t, 0), b = surface.corner(t, 1), c = surface.corner(t, 2);
        const float n = glm::cross(b - a, c - a).y;
        if (a.y == y && b.y == y && c.y == y && n * normalY > 0.0f) return t;
    }
    return surface.triangleCount();
}

}  // namespace

TEST(SurfaceInterior, FindsWhereOneClosedPartLiesInsideAnother) {
    // A 20 mm cube half sunk into the top of a 200 x 40 x 200 mm slab.
    Character character = proceduralCharacter("boxes", "", "skin");
    auto surface = reference::CharacterSurface::create(
        character, twoBoxes(glm::vec3(-0.01f, -0.01f, -0.01f), glm::vec3(0.01f, 0.01f, 0.01f)));
    ASSERT_TRUE(surface.ok()) << surface.error().message();
    const reference::SurfaceInterior interior = reference::SurfaceInterior::build(*surface);
    EXPECT_EQ(interior.partCount(), 2u);
    EXPECT_EQ(interior.closedPartCount(), 2u);
    // The cube's bottom face (y = -10 mm) is inside the slab, its top (y = +10 mm) outside.
    const size_t cubeBottom = triangleAtHeight(*surface, -0.01f, -1.0f);
    const size_t cubeTop = triangleAtHeight(*surface, 0.01f, 1.0f);
    ASSERT_LT(cubeBottom, surface->triangleCount());
    ASSERT_LT(cubeTop, surface->triangleCount());
    EXPECT_TRUE(interior.buried(cubeBottom, 0.3f, 0.3f));
    EXPECT_FALSE(interior.buried(cubeTop, 0.3f, 0.3f));
    // The slab's top face: inside the cube where the cube stands on it, outside elsewhere.
    const size_t slabTop = triangleAtHeight(*surface, 0.0f, 1.0f);
    ASSERT_LT(slabTop, surface->triangleCount());
    EXPECT_FALSE(interior.buried(slabTop, 0.2f, 0.2f));
    int insideTheCube = 0, outsideTheCube = 0;
    for (float x = -0.0975f; x < 0.1f; x += 0.005f) {  // never on the cube's faces (x, z = +-0.01)
        for (float z = -0.0975f; z < 0.1f; z += 0.005f) {
            const glm::vec3 a = surface->corner(slabTop, 0), b = surface->corner(slabTop, 1), c = surface->corner(slabTop, 2);
            // Weights of (x, 0, z) in the slab top's plane (the quad's triangle extends linearly).
            const glm::vec3 e1 = b - a, e2 = c - a, d = glm::vec3(x, 0.0f, z) - a;
            const float det = e1.x * e2.z - e1.z * e2.x;
            const float b1 = (d.x * e2.z - d.z * e2.x) / det, b2 = (e1.x * d.z - e1.z * d.x) / det;
            const bool expected = std::abs(x) < 0.01f && std::abs(z) < 0.01f;
            const bool found = interior.buried(slabTop, b1, b2);
            EXPECT_EQ(found, expected) << "at x " << x << " z " << z;
            (expected ? insideTheCube : outsideTheCube) += 1;
        }
    }
    EXPECT_GT(insideTheCube, 0);
    EXPECT_GT(outsideTheCube, 0);
    // The cube's sides cross the slab's top: below it buried, above not, point by point.
    EXPECT_GT(interior.straddlingTriangleCount(), 0u);
}

TEST(SurfaceInterior, AnOpenPartBuriesNothing) {
    // The slab without its top face: a ray count cannot tell inside from outside, so nothing is buried.
    Character character = proceduralCharacter("boxes", "", "skin");
    auto surface = reference::CharacterSurface::create(
        character, twoBoxes(glm::vec3(-0.01f, -0.02f, -0.01f), glm::vec3(0.01f, -0.005f, 0.01f), false));
    ASSERT_TRUE(surface.ok()) << surface.error().message();
    const reference::SurfaceInterior interior = reference::SurfaceInterior::build(*surface);
    EXPECT_EQ(interior.closedPartCount(), 1u);
    EXPECT_EQ(interior.buriedTriangleCount(), 0u);
    EXPECT_EQ(interior.straddlingTriangleCount(), 0u);
}

TEST(ReferenceFurnace, SurfaceInsideTheBodyGivesNoLight) {
    // A 20 x 10 x 20 mm box inside the slab, its top 1 mm under the slab's top,
    // lit by the uniform ambient alone (AO is 1 in the reference, so the ambient
    // reaches the buried faces too). The slab's top above it is a flat skin
    // surface, whose scattered light is E x albedo (the plane furnace). Counting
    // the buried box's top, 1 mm below, added 0.40 of the lit level in red
    // (sum of w_i exp(-1 / 2 v_i) over the wide Gaussians) before; the bound
    // is the plane furnace's 0.3%.
    Scene scene = bareScene();
    scene.settings.ambient = glm::vec3(0.1f);
    scene.settings.sss.mix = 0.5f;
    scene.characters.push_back(proceduralCharacter("boxes", "", "skin"));
    std::vector<Model> models;
    models.push_back(twoBoxes(glm::vec3(-0.01f, -0.011f, -0.01f), glm::vec3(0.01f, -0.001f, 0.01f)));
    auto renderer = reference::ReferenceRenderer::create(scene, std::move(models), reference::ReferenceOptions{});
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    EXPECT_EQ(renderer->stats().buriedTriangles, 12u);  // the inner box, all of it

    const std::vector<glm::vec4> values = renderer->diffuseAlongRays({downAt(0.0f, 0.0f), downAt(0.003f, -0.004f)}, 0.0f, 0.02f);
    for (const glm::vec4& v : values) {
        ASSERT_EQ(v.a, 1.0f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c] / 0.1f, 1.0f, 0.003f) << "channel " << c;
    }
}
