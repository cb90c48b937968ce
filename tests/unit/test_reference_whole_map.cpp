// The CPU reference lights with the environment map as loaded, never with
// what the engine leaves of it after taking its dominant light out
// (docs/environment.md, "The dominant light"): its error measures the split.
#include "env/DominantLight.h"
#include "env/EnvironmentMap.h"
#include "raytrace/Bvh.h"
#include "reference/ReferenceLighting.h"

#include <gtest/gtest.h>

using namespace dermis;

namespace {

// A point facing the built-in sky's sun, towards (0.4, 0.6, 0.7), or tilted from it.
reference::SurfacePoint pointFacing(const glm::vec3& normal) {
    reference::SurfacePoint p;
    p.geometricNormal = glm::normalize(normal);
    p.shadingNormal = p.geometricNormal;
    p.roughness = 0.35f;
    p.rhoS = 0.18f;
    return p;
}

}  // namespace

// With extract_light auto (the default) and off, the reference built from the
// scene gives the same environment irradiance as one given the whole map;
// one given the map without the sun gives 40% less facing the sun, so the
// comparison would see a reference that lit with the split.
TEST(ReferenceWholeMap, TheReferenceLightsWithTheMapAsLoaded) {
    const raytrace::Bvh nothing = raytrace::Bvh::build({});
    Scene scene;
    scene.settings.ambient = glm::vec3(0.0f);
    scene.environment.source = "sky";
    const Image sky = makeBuiltInEnvironment("sky").value();
    const reference::ReferenceLighting whole(scene, nothing, sky);
    LightExtractionSettings extraction;
    extraction.maxSolidAngleSr = 0.2f;
    const EnvironmentSplit split = extractDominantLights(sky, extraction);
    ASSERT_EQ(split.lights.size(), 1u);
    const reference::ReferenceLighting withoutSun(scene, nothing, split.remainder);
    for (const EnvironmentLightExtraction mode : {EnvironmentLightExtraction::Auto, EnvironmentLightExtraction::Off}) {
        scene.environment.extractLight = mode;
        const auto created = reference::ReferenceLighting::create(scene, nothing);
        ASSERT_TRUE(created.ok()) << created.error().message();
        for (const glm::vec3& n : {glm::vec3(0.4f, 0.6f, 0.7f), glm::vec3(0, 1, 0), glm::vec3(-0.4f, 0.2f, 0.7f)}) {
            EXPECT_EQ(created->environmentIrradiance(pointFacing(n)), whole.environmentIrradiance(pointFacing(n)));
        }
    }
    const reference::SurfacePoint facingSun = pointFacing(glm::vec3(0.4f, 0.6f, 0.7f));
    EXPECT_LT(withoutSun.environmentIrradiance(facingSun).g, 0.6f * whole.environmentIrradiance(facingSun).g);
}
