// Which characters a shadow map keeps (plan/ShadowCasters.h) and how the
// map reaches them (plan/LightSetup.h), on hand-placed 0.2 m boxes: a
// receiver at the origin, and casters towards the light, beside it, beyond it.
#include "plan/LightSetup.h"
#include "plan/ShadowCasters.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace dermis;

namespace {

Bounds box(const glm::vec3& centre) { return {centre - glm::vec3(0.1f), centre + glm::vec3(0.1f)}; }

// The light's block with its map fitted around `receiver`.
gpu::GpuLight fitted(const Light& light, const Bounds& receiver) {
    ShadowSettings shadows;
    shadows.mapSize = 2048;
    return setupLights({light}, receiver, shadows).block.lights[0];
}

Light sun(float angularDiameterDeg = 0.0f) {
    Light light;
    light.type = LightType::Directional;
    light.direction = {0.0f, -1.0f, 0.0f};
    light.angularDiameterDeg = angularDiameterDeg;
    light.castsShadow = true;
    return light;
}

std::vector<int> keptOf(const Light& light, const std::vector<Bounds>& bounds, const std::vector<bool>& visible) {
    return chooseShadowCasters(fitted(light, bounds[0]), bounds, visible).kept;
}

}  // namespace

TEST(ShadowCasters, DirectionalKeepsWhatIsAboveAVisibleReceiver) {
    const std::vector<Bounds> bounds = {box({0, 0, 0}), box({0.05f, 1.0f, 0}), box({1.0f, 1.0f, 0}), box({0, -1.0f, 0})};
    const std::vector<bool> visible = {true, false, false, false};
    const ShadowCasters casters = chooseShadowCasters(fitted(sun(), bounds[0]), bounds, visible);
    EXPECT_EQ(casters.kept, (std::vector<int>{0, 1}));  // beside (2) and below (3) cannot shade it
    EXPECT_EQ(casters.culledBecause[1], "");
    EXPECT_NE(casters.culledBecause[2], "");
    EXPECT_NE(casters.culledBecause[3], "");
    EXPECT_FLOAT_EQ(casters.reach.max.y, 1.1f);
}

TEST(ShadowCasters, DirectionalPenumbraWidensTheFootprint) {
    // 0.25 m beside the receiver's edge, 0.9 m above it: a 29-degree-wide light's penumbra
    // reaches (1.1 + 0.1) tan 14.5 = 0.31 m across (top of the caster to the bottom of the
    // receiver), a delta light's only the filter's 4 texels.
    const std::vector<Bounds> bounds = {box({0, 0, 0}), box({0.45f, 1.0f, 0})};
    EXPECT_EQ(keptOf(sun(0.0f), bounds, {true, false}), std::vector<int>{0});
    EXPECT_EQ(keptOf(sun(29.0f), bounds, {true, false}), (std::vector<int>{0, 1}));
}

TEST(ShadowCasters, NoVisibleReceiverKeepsNothing) {
    const std::vector<Bounds> bounds = {box({0, 0, 0}), box({0, 1.0f, 0})};
    const ShadowCasters casters = chooseShadowCasters(fitted(sun(), bounds[0]), bounds, {false, false});
    EXPECT_TRUE(casters.kept.empty());
    EXPECT_EQ(casters.culledBecause[1], "no character on screen to receive its shadow");
}

TEST(ShadowCasters, PointAndSpotLightsKeepWhatIsBetweenThemAndAReceiver) {
    for (const LightType type : {LightType::Point, LightType::Spot}) {
        Light lamp;
        lamp.type = type;
        lamp.positionM = {0.0f, 2.0f, 0.0f};
        lamp.direction = {0.0f, -1.0f, 0.0f};
        lamp.castsShadow = true;
        const std::vector<Bounds> bounds = {box({0, 0, 0}), box({0.1f, 1.0f, 0}), box({1.0f, 1.0f, 0}),
                                            box({0, -1.0f, 0}), box({0, 3.0f, 0})};
        EXPECT_EQ(keptOf(lamp, bounds, {true, false, false, false, false}), (std::vector<int>{0, 1}))
            << int(type);
    }
}

TEST(ShadowCasters, TheMapReachesTheKeptCastersAndStaysTheReceiversAcross) {
    const Bounds receiver = box({0, 0, 0});
    const Bounds caster = box({0, 3.0f, 0});
    ShadowSettings shadows;
    const gpu::GpuLight alone = setupLights({sun()}, receiver, shadows).block.lights[0];
    const gpu::GpuLight reaching = setupLights({sun()}, receiver, shadows, {Bounds{receiver.min, caster.max}}).block.lights[0];
    const auto depthOf = [](const gpu::GpuLight& g, const glm::vec3& p) {
        return glm::dot(p - g.positionM, g.direction);
    };
    EXPECT_GE(depthOf(reaching, caster.max), reaching.shadowNearM);  // the caster's top is inside
    EXPECT_LT(depthOf(alone, caster.max), alone.shadowNearM);        // it was before the near plane
    EXPECT_FLOAT_EQ(reaching.shadowTexelM, alone.shadowTexelM);    // the same texels across
    // Casters inside the receivers' sphere change nothing.
    const gpu::GpuLight inside = setupLights({sun()}, receiver, shadows, {receiver}).block.lights[0];
    EXPECT_EQ(0, std::memcmp(&inside, &alone, sizeof inside));
}
