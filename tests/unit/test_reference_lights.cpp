// The CPU reference's sized lights (docs/shadows.md): the penumbra of a
// straight edge against the disc-segment closed form (support/PenumbraEdge.h),
// point lights casting shadow rays, and the visibility masks that steer the
// integrator's edge refinement.
#include "PenumbraEdge.h"

#include "raytrace/Bvh.h"
#include "reference/ReferenceLighting.h"

#include <gtest/gtest.h>

#include <glm/gtc/constants.hpp>

#include <cmath>

using namespace dermis;
using namespace dermis::test;

namespace {

constexpr double kPi = 3.14159265358979323846;
// The blocker: a horizontal quad at this height over x < 0 (its edge runs along z at x = 0).
constexpr float kBlockerHeightM = 0.05f;

raytrace::Bvh blockerBvh() {
    const float h = kBlockerHeightM;
    const glm::vec3 a(-1.0f, h, -1.0f), b(0.0f, h, -1.0f), c(0.0f, h, 1.0f), d(-1.0f, h, 1.0f);
    return raytrace::Bvh::build({a, b, c, a, c, d});
}

Scene bareLitScene(const Light& light) {
    Scene scene;
    scene.settings.ambient = glm::vec3(0.0f);
    scene.settings.energyConservation = false;
    scene.lights.push_back(light);
    return scene;
}

reference::SurfacePoint floorPoint(double xM) {
    reference::SurfacePoint p;
    p.positionM = glm::vec3(float(xM), 0.0f, 0.0f);
    p.geometricNormal = p.shadingNormal = glm::vec3(0.0f, 1.0f, 0.0f);
    return p;
}

Light sunOfDiameter(float diameterDeg) {
    Light light;
    light.type = LightType::Directional;
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.angularDiameterDeg = diameterDeg;
    return light;
}

constexpr float kLampHeightM = 0.3f;

Light lampOfRadius(LightType type, float radiusM) {
    Light light;
    light.type = type;
    light.positionM = glm::vec3(0.0f, kLampHeightM, 0.0f);
    light.direction = glm::vec3(0.0f, -1.0f, 0.0f);
    light.spotInnerDeg = 60.0f;
    light.spotOuterDeg = 70.0f;
    light.radiusM = radiusM;
    return light;
}

// Visibility along the floor from the reference (irradiance over the
// unshadowed irradiance, which the test computes: N.L / r^2 of the centre) and
// from the closed form, at the same xs.
struct Profiles {
    std::vector<double> xsM, reference, closedForm;
};

Profiles sampleProfiles(const Light& light, double fromM, double toM, int count) {
    const raytrace::Bvh bvh = blockerBvh();
    const Scene scene = bareLitScene(light);
    const reference::ReferenceLighting lighting(scene, bvh);
    Profiles p;
    for (int i = 0; i < count; ++i) {
        const double x = fromM + (toM - fromM) * i / (count - 1);
        double unshadowed = 1.0, delta = 0.0, sinRadius = 0.0;
        if (light.type == LightType::Directional) {
            delta = std::atan(x / kBlockerHeightM);  // the edge plane's angle from the vertical
            sinRadius = std::sin(0.5 * light.angularDiameterDeg * kPi / 180.0);
        } else {
            const double d2 = x * x + double(kLampHeightM) * kLampHeightM;
            unshadowed = kLampHeightM / std::sqrt(d2) / d2;
            delta = std::atan2(kBlockerHeightM, -x) - std::atan2(double(kLampHeightM), -x);
            sinRadius = light.radiusM / std::sqrt(d2);
        }
        p.xsM.push_back(x);
        p.reference.push_back(lighting.irradiance(floorPoint(x)).x / unshadowed);
        p.closedForm.push_back(discSegmentVisibility(std::sin(delta) / sinRadius));
    }
    return p;
}

// Bounds: the 10-90 width within 5% of the closed form's. A 64-ray estimate
// moves a crossing by about one stratum's share of the disc, ~1/64 of the
// penumbra (measured: within 1.7%); 5% still fails a penumbra 1.2x too wide or
// too narrow (scaling the angular radius or the sphere radius in
// ReferenceLighting by 1.2 and 1/1.2 gave ratios 1.21 and 0.83-0.84). The whole
// profile stays within 0.04 of the closed form: 2.5 strata of 64 (measured at
// most 0.031; the 1.2x mutations gave 0.072-0.081).
void expectPenumbraMatches(const Profiles& p, const char* what) {
    const double measured = width10To90(p.xsM, p.reference);
    const double expected = width10To90(p.xsM, p.closedForm);
    double worst = 0.0;
    for (size_t i = 0; i < p.xsM.size(); ++i) worst = std::max(worst, std::fabs(p.reference[i] - p.closedForm[i]));
    std::printf("%s: 10-90 width %.3f mm, closed form %.3f mm (ratio %.4f); worst visibility error %.4f\n", what,
                measured * 1e3, expected * 1e3, measured / expected, worst);
    EXPECT_NEAR(measured / expected, 1.0, 0.05) << what;
    EXPECT_LT(worst, 0.04) << what;
}

}  // namespace

TEST(ReferenceLights, FiveDegreeSunPenumbraMatchesTheDiscSegment) {
    // Full width 2 h tan(2.5 deg) = 4.37 mm; sample 8 mm around the edge at 20 um.
    expectPenumbraMatches(sampleProfiles(sunOfDiameter(5.0f), -0.004, 0.004, 401), "5-degree sun");
}

TEST(ReferenceLights, SunPenumbraWidthFollowsTheGap) {
    // The sun (0.53 deg): full width 2 h tan(0.265 deg) = 0.46 mm.
    expectPenumbraMatches(sampleProfiles(sunOfDiameter(0.53f), -0.0006, 0.0006, 241), "0.53-degree sun");
}

TEST(ReferenceLights, PointAndSpotSpherePenumbraMatchesTheDiscSegment) {
    // w = 2 R (d_r - d_b) / d_b = 2 x 0.02 x 0.05 / 0.25 = 8 mm.
    for (LightType type : {LightType::Point, LightType::Spot}) {
        expectPenumbraMatches(sampleProfiles(lampOfRadius(type, 0.02f), -0.008, 0.008, 401),
                              type == LightType::Point ? "point, radius 20 mm" : "spot, radius 20 mm");
    }
}

TEST(ReferenceLights, DeltaLightsCastOneHardRay) {
    // Size 0: the visibility is 0 or 1 on either side of the geometric edge,
    // here at x = 0 for the sun and the lamp straight above it.
    for (const Light& light : {sunOfDiameter(0.0f), lampOfRadius(LightType::Point, 0.0f)}) {
        const Profiles p = sampleProfiles(light, -0.001, 0.001, 21);
        for (size_t i = 0; i < p.xsM.size(); ++i) {
            if (std::fabs(p.xsM[i]) < 1e-6) continue;
            EXPECT_NEAR(p.reference[i], p.xsM[i] > 0.0 ? 1.0 : 0.0, 1e-5) << "x = " << p.xsM[i];
        }
    }
}

TEST(ReferenceLights, PointLightsCastShadowRays) {
    // A delta point light 0.3 m above the floor at x = 0.1 and the blocker over
    // x < 0 at 0.05 m: the shadow ends where the ray over the edge lands,
    // x = 0.1 - 0.1 x 0.3 / 0.25 = -0.02 m.
    Light light = lampOfRadius(LightType::Point, 0.0f);
    light.positionM.x = 0.1f;
    const raytrace::Bvh bvh = blockerBvh();
    const Scene scene = bareLitScene(light);
    const reference::ReferenceLighting lighting(scene, bvh);
    EXPECT_EQ(lighting.irradiance(floorPoint(-0.021)).x, 0.0f);
    EXPECT_GT(lighting.irradiance(floorPoint(-0.019)).x, 0.0f);
    EXPECT_GT(lighting.irradiance(floorPoint(0.05)).x, 0.0f);
}

TEST(ReferenceLights, PenumbraSamplesRefineAgainstLitAndUmbra) {
    const raytrace::Bvh bvh = blockerBvh();
    const Scene scene = bareLitScene(sunOfDiameter(5.0f));
    const reference::ReferenceLighting lighting(scene, bvh);
    auto visibilityAt = [&](double x) {
        reference::LightVisibility v;
        lighting.irradiance(floorPoint(x), &v);
        return v;
    };
    const reference::LightVisibility umbra = visibilityAt(-0.01), penumbra = visibilityAt(0.0005),
                                     lit = visibilityAt(0.01), lit2 = visibilityAt(0.02);
    EXPECT_TRUE(lit.disagreesWith(penumbra));
    EXPECT_TRUE(penumbra.disagreesWith(umbra));
    EXPECT_TRUE(lit.disagreesWith(umbra));
    EXPECT_FALSE(lit.disagreesWith(lit2));
}
