// renderThicknessMm against the known thickness of the procedural shapes:
// the sphere's chord through its centre, the wedge's closed-form depth along
// its tilted face normal, a single-sided plane (no exit) and the background.
#include "ReferenceTestScenes.h"

#include "procedural/ProceduralShapes.h"
#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;
using namespace dermis::test;

namespace {

Image thickness(const Scene& scene, std::vector<Model> models, int width, int height) {
    auto renderer = reference::ReferenceRenderer::create(scene, std::move(models), reference::ReferenceOptions{});
    EXPECT_TRUE(renderer.ok());
    return renderer->renderThicknessMm(width, height);
}

// The world point a pixel centre's ray meets on the plane y = yM.
glm::vec3 onPlaneY(const Camera& camera, int width, int height, int x, int y, float yM) {
    const raytrace::Ray ray = reference::ReferenceRenderer::cameraRay(camera, width, height, x, y);
    return ray.origin + ray.direction * ((yM - ray.origin.y) / ray.direction.y);
}

}  // namespace

TEST(ReferenceThickness, SphereIsItsDiameterAlongTheNormal) {
    // The facet normal of a 64 x 32 UV sphere points through the centre within half a
    // facet (2.8 degrees): the chord is then 2 R cos(angle) >= 0.9988 x 200 mm, and the
    // facets lie within R (1 - cos(pi / 32)) = 0.5 % inside the sphere: 1 % holds both.
    Scene scene = sphereScene();
    scene.characters.pop_back();  // no card
    std::vector<Model> models = sphereSceneModels(false);
    models.pop_back();
    const Image image = thickness(scene, std::move(models), 32, 24);
    int covered = 0;
    for (const glm::vec4& texel : image.texels) {
        if (texel.a == 0.0f) {
            EXPECT_EQ(texel, glm::vec4(0.0f));
            continue;
        }
        ++covered;
        EXPECT_EQ(texel.a, 1.0f);
        EXPECT_NEAR(texel.r / (2.0f * kSphereRadiusM * 1000.0f), 1.0f, 0.01f);
    }
    EXPECT_GT(covered, 200);
}

TEST(ReferenceThickness, WedgeFollowsItsClosedForm) {
    // Seen from above, a point of the top face at x has thickness t(x) = 1 + 19 x / 0.2 mm;
    // each face is tilted by s = t'(x) / 2 = 0.0475, and the ray along minus its normal
    // reaches the bottom face after tau = t(x) sqrt(1 + s^2) / (1 - s^2) (the two faces'
    // planes intersected with the ray). Float rounding of a 1 mm distance at 0.3 m from
    // the camera: ~1e-4 mm; the bound 0.01 mm is far below the 5 % (0.05 to 1 mm) a
    // missing tilt correction makes.
    Scene scene;
    scene.camera.positionM = glm::vec3(0.1f, 0.3f, 0.0f);
    scene.camera.targetM = glm::vec3(0.1f, 0.0f, 0.0f);
    scene.camera.up = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.verticalFovDeg = 30.0f;
    scene.characters.push_back(proceduralCharacter("wedge", "wedge", "skin"));
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("wedge"));
    constexpr int kWidth = 40, kHeight = 20;
    const Image image = thickness(scene, std::move(models), kWidth, kHeight);
    const float s = 0.5f * (kWedgeThickMm - kWedgeThinMm) / (kWedgeLengthM * 1000.0f);
    int checked = 0;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            // The top face's height is at most 10 mm: find x on it by one fixed-point step.
            glm::vec3 p = onPlaneY(scene.camera, kWidth, kHeight, x, y, 0.0f);
            const float tMm0 = kWedgeThinMm + (kWedgeThickMm - kWedgeThinMm) * p.x / kWedgeLengthM;
            p = onPlaneY(scene.camera, kWidth, kHeight, x, y, 0.0005f * tMm0);
            const float tMm = kWedgeThinMm + (kWedgeThickMm - kWedgeThinMm) * p.x / kWedgeLengthM;
            const bool inside = p.x > 0.002f && p.x < kWedgeLengthM - 0.002f && std::fabs(p.z) < 0.5f * kWedgeDepthM - 0.002f;
            if (!inside) continue;
            ++checked;
            ASSERT_EQ(image.at(x, y).a, 1.0f);
            const float expected = tMm * std::sqrt(1.0f + s * s) / (1.0f - s * s);
            EXPECT_NEAR(image.at(x, y).r, expected, 0.01f) << "pixel " << x << ", " << y;
        }
    }
    EXPECT_GT(checked, 200);  // most of the 800 pixels see the top face
}

TEST(ReferenceThickness, OpenSurfaceHasNoExit) {
    // The plane has nothing of its own behind it; another character's surface does not count.
    Scene scene = bareScene();
    scene.camera.positionM = glm::vec3(0.0f, 0.3f, 0.05f);
    scene.camera.targetM = glm::vec3(0.0f);
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    scene.characters.push_back(proceduralCharacter("floor", "", "none"));
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    // Another character 5 cm under the plane, facing up: the ray through the plane meets it.
    models.push_back(quadModel(glm::vec3(-1, -0.05f, -1), glm::vec3(-1, -0.05f, 1), glm::vec3(1, -0.05f, 1),
                               glm::vec3(1, -0.05f, -1)));
    const Image image = thickness(scene, std::move(models), 8, 6);
    for (const glm::vec4& texel : image.texels) {
        ASSERT_EQ(texel.a, 1.0f);
        EXPECT_EQ(texel.r, reference::kNoExitThicknessMm);
    }
}
