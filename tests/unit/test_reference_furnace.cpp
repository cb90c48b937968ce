// Furnace checks of the CPU reference (docs/reference.md): a uniformly lit
// plane must come back unchanged away from its border, and characters without
// a profile are plain Lambert.
#include "ReferenceTestScenes.h"

#include "reference/ReferenceRenderer.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dermis;
using namespace dermis::test;

namespace {

std::vector<raytrace::Ray> pointsAwayFromTheBorder() {
    std::vector<raytrace::Ray> rays;
    for (int i = 0; i < 40; ++i) {
        // Up to 0.3 m from the centre of the 1 m plane: the profile reaches 14 mm.
        const float x = 0.3f * std::sin(1.7f * float(i));
        const float z = 0.3f * std::cos(2.3f * float(i));
        rays.push_back(downAt(x, z));
    }
    return rays;
}

}  // namespace

TEST(ReferenceFurnace, UniformlyLitPlaneIsUniform) {
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove(2.0f));
    scene.settings.sss.mix = 0.5f;
    scene.settings.ambient = glm::vec3(0.1f);
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    scene.characters[0].material.albedo = glm::vec3(0.8f, 0.6f, 0.5f);
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    auto renderer = reference::ReferenceRenderer::create(scene, std::move(models), reference::ReferenceOptions{});
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();

    const std::vector<glm::vec4> values = renderer->diffuseAlongRays(pointsAwayFromTheBorder(), 0.0f, 0.02f);
    // E = 2 + 0.1; albedo^0.5 before and after the scattering: E x albedo.
    const glm::vec3 expected = 2.1f * glm::vec3(0.8f, 0.6f, 0.5f);
    for (const glm::vec4& v : values) {
        ASSERT_EQ(v.a, 1.0f);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c] / expected[c], 1.0f, 0.003f) << "channel " << c;
    }
}

TEST(ReferenceFurnace, OpaqueCharacterIsLambertian) {
    Scene scene = bareScene();
    Light light = sunFromAbove(1.5f);
    light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    scene.lights.push_back(light);
    scene.settings.energyConservation = true;
    scene.characters.push_back(proceduralCharacter("plane", "plane", "none"));
    scene.characters[0].material.albedo = glm::vec3(0.5f, 0.4f, 0.3f);
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    auto renderer = reference::ReferenceRenderer::create(scene, std::move(models), reference::ReferenceOptions{});
    ASSERT_TRUE(renderer.ok()) << renderer.error().message();
    EXPECT_EQ(renderer->stats().baseCells, 0u);

    const std::vector<glm::vec4> values = renderer->diffuseAlongRays({downAt(0.1f, -0.2f)}, 0.0f, 0.02f);
    // E x albedo x the energy factors in (at N.L) and out (N.V = 1: the ray looks straight down).
    const raytrace::Bvh noOccluders = raytrace::Bvh::build({});
    const reference::ReferenceLighting lighting(scene, noOccluders);
    const Material& material = scene.characters[0].material;
    const float nDotL = -light.direction.y;
    const float in = lighting.energyLeftForDiffuse(nDotL, material.roughness, material.rhoS);
    const float out = lighting.energyLeftForDiffuse(1.0f, material.roughness, material.rhoS);
    EXPECT_LT(in, 1.0f);
    EXPECT_LT(out, 1.0f);
    const glm::vec3 expected = 1.5f * nDotL * in * material.albedo * out;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(values[0][c], expected[c], 1e-5f) << "channel " << c;
}

TEST(ReferenceFurnace, BackgroundIsZeroWithZeroAlpha) {
    Scene scene = bareScene();
    scene.lights.push_back(sunFromAbove());
    scene.characters.push_back(proceduralCharacter("plane", "plane", "skin"));
    std::vector<Model> models;
    models.push_back(proceduralModelWithoutMaps("plane"));
    auto renderer = reference::ReferenceRenderer::create(scene, std::move(models), reference::ReferenceOptions{});
    ASSERT_TRUE(renderer.ok());
    const raytrace::Ray up{glm::vec3(0.0f, 0.1f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)};
    EXPECT_EQ(renderer->diffuseAlongRays({up}, 0.0f, 10.0f)[0], glm::vec4(0.0f));
}
