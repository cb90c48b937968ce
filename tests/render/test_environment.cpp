// Environment light in the frame (docs/environment.md) against closed forms:
// the white furnace in both modes, rotation invariance, and the skybox.
#include "RenderFixture.h"
#include "TestSupport.h"

#include "brdf/EnergyTable.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace dermis;

namespace {

class EnvironmentFrame : public test::RenderFixture {};

// A 10 cm skin sphere of albedo 1 seen from 40 cm, alone in a uniform white
// environment: nothing but the environment lights it.
std::vector<std::string> furnaceScene(const char* mode, const char* occlusion) {
    return {"camera.position_m=[0,0,0.4]", "camera.up=[0,1,0]",
            "camera.target_m=[0,0,0]",
            "lights=[]",
            R"(characters=[{"name": "ball", "mesh": {"procedural": "sphere"},
                "material": {"albedo": [1, 1, 1], "roughness": 0.3, "rho_s": 0.18, "profile": "skin"}}])",
            std::string(R"(environment={"source": "uniform", "intensity": 1, "occlusion": ")") + occlusion + "\"}",
            std::string("mode=") + mode};
}

// The hemispherical mean of rho_dt, 2 int_0^1 rho_dt(mu, m) mu dmu, by 32-point
// midpoint quadrature of brdf/EnergyTable.h's rhoDt (not through the table).
double averageRhoDt(float m) {
    constexpr int kNodes = 32;
    double sum = 0.0;
    for (int i = 0; i < kNodes; ++i) {
        const double mu = (i + 0.5) / kNodes;
        sum += rhoDt(float(mu), m) * mu / kNodes;
    }
    return 2.0 * sum;
}

}  // namespace

// White furnace: L = 1 everywhere, albedo 1. Energy conservation (Chappuis
// 2011 §2.6) predicts per pixel, in the engine's units (the diffuse is
// irradiance x albedo, as for every light, docs/environment.md):
//   radiance = pi (1 - rho_s rho_avg(m)) (1 - rho_s rho_dt(N.V, m)) + rho_s rho_dt(N.V, m),
// the first the diffuse (uniform irradiance pi, so the SSS blurs keep it),
// the second the split-sum specular of a uniform map (prefiltered = 1, no
// occlusion on a convex sphere). N.V from the exact sphere.
TEST_F(EnvironmentFrame, WhiteFurnaceMatchesEnergyConservationInBothModes) {
    constexpr int kWidth = 160;
    constexpr int kHeight = 90;
    for (const char* mode : {"ss", "ts"}) {
        for (const char* occlusion : {"none", "transfer"}) {
            load("furnace.json", furnaceScene(mode, occlusion));
            const Image image = render(Aov::Radiance, kWidth, kHeight);
            ASSERT_EQ(test::countNonFinite(image), 0u);
            const Material& material = mScene->characters[0].material;
            const double diffuseShare = 1.0 - material.rhoS * averageRhoDt(material.roughness);
            const glm::dvec3 eye(0.0, 0.0, 0.4);
            const double radiusM = 0.1;
            const double tanHalf = std::tan(glm::radians(double(mScene->camera.verticalFovDeg)) / 2.0);
            const double aspect = double(kWidth) / kHeight;
            double worst = 0.0;
            int checked = 0;
            for (int y = 0; y < kHeight; ++y) {
                for (int x = 0; x < kWidth; ++x) {
                    const glm::dvec3 ray = glm::normalize(glm::dvec3((2.0 * (x + 0.5) / kWidth - 1.0) * tanHalf * aspect,
                                                                     (1.0 - 2.0 * (y + 0.5) / kHeight) * tanHalf, -1.0));
                    const double b = glm::dot(eye, ray);
                    const double discriminant = b * b - (glm::dot(eye, eye) - radiusM * radiusM);
                    if (discriminant <= 0.0) continue;
                    const glm::dvec3 hit = eye + ray * (-b - std::sqrt(discriminant));
                    const double nDotV = glm::dot(hit / radiusM, -ray);
                    // Facets: the tessellated sphere's normals and silhouette drift from the exact
                    // sphere's where N.V is small; rho_dt changes fastest there.
                    if (nDotV < 0.3) continue;
                    const double specular = material.rhoS * rhoDt(float(nDotV), material.roughness);
                    const double expected = glm::pi<double>() * diffuseShare * (1.0 - specular) + specular;
                    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(image.at(x, y)[c] / expected - 1.0));
                    ++checked;
                }
            }
            std::printf("white furnace %s, occlusion %s: %d pixels, worst relative error %.4f%%\n", mode, occlusion,
                        checked, 100.0 * worst);
            ASSERT_GT(checked, 1000);
            // 0.5% (the goal): the irradiance and albedo targets are half floats (0.05% each),
            // the energy table is read bilinearly (5e-4 of rho_dt, x rho_s = 0.18), the averaged
            // albedo by the trapezoid rule over 64 columns, and the SH projection of a constant
            // is exact to 1e-4 (SphericalHarmonics tests). Measured 0.20-0.31%. Dropping the
            // environment's diffuse share (1 - rho_s rho_avg) in lighting.frag fails it by 2.7%.
            EXPECT_LT(worst, 0.005) << mode << ", occlusion " << occlusion;
        }
    }
}

// Turning the environment, the character, the camera and the lights by one
// rotation turns the whole scene: the image must not change. Exercises the SH
// rotation (bands 1 and 2), the object-space light of the per-vertex
// transfer, and the map lookups of the skybox and the specular.
TEST_F(EnvironmentFrame, RotatingEnvironmentAndSceneTogetherLeavesTheImageUnchanged) {
    constexpr float kAngleDeg = 50.0f;
    const glm::mat3 rotation = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(kAngleDeg), glm::vec3(0, 1, 0)));
    for (const char* extraction : {"off", "auto"}) for (const char* mode : {"ss", "ts"}) {
        const std::vector<std::string> common = {"lights=[]", std::string("mode=") + mode,
                                                 "environment.source=\"studio\"", "ssao.enabled=false",
                                                 std::string("environment.extract_light=") + extraction};
        std::vector<std::string> base = common;
        load("default.json", base);
        const Camera camera = mScene->camera;
        const Image unturned = render(Aov::Final, 160, 90);
        std::vector<std::string> turned = common;
        const glm::vec3 position = rotation * camera.positionM;
        const glm::vec3 target = rotation * camera.targetM;
        const glm::vec3 up = rotation * camera.up;
        char text[256];
        std::snprintf(text, sizeof text, "camera.position_m=[%.9g,%.9g,%.9g]", position.x, position.y, position.z);
        turned.push_back(text);
        std::snprintf(text, sizeof text, "camera.target_m=[%.9g,%.9g,%.9g]", target.x, target.y, target.z);
        turned.push_back(text);
        std::snprintf(text, sizeof text, "camera.up=[%.9g,%.9g,%.9g]", up.x, up.y, up.z);
        turned.push_back(text);
        turned.push_back("characters.0.transform.rotation_deg=[0," + std::to_string(kAngleDeg) + ",0]");
        turned.push_back("environment.rotation={\"axis\": [0, 1, 0], \"angle_deg\": " + std::to_string(kAngleDeg) + "}");
        load("default.json", turned);
        const Image image = render(Aov::Final, 160, 90);
        ASSERT_EQ(image.texels.size(), unturned.texels.size());
        int differing = 0;
        float largest = 0.0f;
        for (size_t i = 0; i < image.texels.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                const float difference = std::abs(image.texels[i][c] - unturned.texels[i][c]);
                largest = std::max(largest, difference);
                differing += difference > 1.5f / 255.0f ? 1 : 0;
            }
        }
        std::printf("rotation invariance %s, extract_light %s: largest difference %.1f/255, %d channels over 1/255\n",
                    mode, extraction, largest * 255.0f, differing);
        // 1/255 (the goal), rounding included: the two frames rasterise the same view-space
        // geometry through differently rounded transforms (measured: at most 1 step). Turning
        // the environment by -50 degrees instead fails by 200 steps; giving the transfer the
        // world-space light instead of the character's object-space one, by 78.
        if (std::string(extraction) == "off") {
            EXPECT_EQ(differing, 0) << mode;
        } else {
            // With the studio's key box taken out as a light, its soft shadow map is rasterised
            // through the turned transforms too: measured 2 channels of 28,800 at 2/255 (texture
            // space), none in screen space: rounding at the shadow's edge, bounded at that step.
            EXPECT_LE(largest, 2.5f / 255.0f) << mode;
            EXPECT_LE(differing, 8) << mode;
        }
    }
}

TEST_F(EnvironmentFrame, SkyboxRunsOnlyWhereTheEnvironmentIsDrawnBehind) {
    load("furnace.json", {"environment={\"source\": \"uniform\", \"intensity\": 0.25}",
                          "characters.0.transform.scale=0.05"});
    const Image image = render(Aov::Radiance, 64, 36);
    ASSERT_TRUE(pass("skybox") && pass("skybox")->executed);
    // The shrunken plane covers the middle; the corners look past it at the map: 0.25
    // everywhere (half-float colour: 1e-3), where the composite wrote the black background.
    EXPECT_NEAR(image.at(0, 0).g, 0.25f, 1e-3f);
    EXPECT_GT(std::abs(image.at(32, 18).g - 0.25f), 0.01f) << "the plane, not the sky";

    load("furnace.json", {"environment={\"source\": \"uniform\", \"background\": false}"});
    render(Aov::Radiance, 64, 36);
    EXPECT_FALSE(pass("skybox")->executed);
    EXPECT_NE(pass("skybox")->culledBecause.find("background is false"), std::string::npos);

    load("furnace.json");
    render(Aov::Final, 64, 36);
    EXPECT_NE(pass("skybox")->culledBecause.find("no environment"), std::string::npos);

    load("furnace.json", {"environment={\"source\": \"uniform\"}"});
    render(Aov::Irradiance, 64, 36);
    const PassSummary* skybox = pass("skybox");
    EXPECT_TRUE(skybox == nullptr || !skybox->executed);
}

// The LEAN variants give the environment's specular of characters with LEAN
// maps through the blurred LEAN lobe (include/LeanLights.glsl), the variant c
// through the KS lobe in the lighting pass. Under a uniform environment the
// split sum is rho_s rho_dt(N.V, m) L in both, so the two specular AOVs of
// the head (which has LEAN maps) must agree on average, the LEAN lobe's
// width (base m plus the normal map's slope variance) aside. 5% (measured
// 0.979); leaving the environment out of the LEAN lobe makes the LEAN
// pixels' specular 0 and fails it by 100%.
TEST_F(EnvironmentFrame, LeanVariantsCarryTheEnvironmentsSpecular) {
    const std::vector<std::string> common = {"lights=[]", "ambient=[0,0,0]", "ssao.enabled=false",
                                             R"(environment={"source": "uniform", "occlusion": "none"})"};
    std::vector<std::string> c = common;
    c.push_back("sss.variant=c");
    load("default.json", c);
    const Image ks = render(Aov::Specular, 160, 90);
    std::vector<std::string> lbb = common;
    lbb.push_back("sss.variant=lbb");
    load("default.json", lbb);
    const Image lean = render(Aov::Specular, 160, 90);
    double ksSum = 0.0, leanSum = 0.0;
    int pixels = 0;
    for (size_t i = 0; i < ks.texels.size(); ++i) {
        if (ks.texels[i].g <= 0.0f) continue;
        ksSum += ks.texels[i].g;
        leanSum += lean.texels[i].g;
        ++pixels;
    }
    ASSERT_GT(pixels, 1000);
    const double ratio = leanSum / ksSum;
    std::printf("environment specular, lbb / c over %d pixels: %.4f\n", pixels, ratio);
    EXPECT_NEAR(ratio, 1.0, 0.05);
}

// Frames without an environment use programs with its code compiled out
// (DERMIS_ENVIRONMENT 0, render/Programs.h); frames with one, the run-time
// programs. An environment of intensity 0 adds exactly nothing, so both must
// give the same head, in both modes and both LEAN ends (the specular AOV
// covers the LEAN lobe's own pass). Both compute the same sums, so the bound
// is below one fp16 step of the targets: 1e-5 of the brightest pixel (measured:
// 0). Broken on purpose (the unlit lighting pass's irradiance scaled by
// 1.001), all three radiance cases failed by 0.00195 of 2.07 (one fp16 step).
TEST_F(EnvironmentFrame, AnEnvironmentOfIntensityZeroRendersAsNone) {
    constexpr int kWidth = 160;
    constexpr int kHeight = 90;
    const std::pair<const char*, Aov> cases[] = {{"sss.variant=lbb", Aov::Radiance},
                                                 {"sss.variant=lbb", Aov::Specular},
                                                 {"sss.variant=c", Aov::Radiance},
                                                 {"mode=ts", Aov::Radiance}};
    for (const auto& [setting, aov] : cases) {
        {
            load("default.json", {setting});
            const Image ids = render(Aov::Object, kWidth, kHeight);
            const Image none = render(aov, kWidth, kHeight);
            load("default.json", {setting, R"(environment={"source": "uniform", "intensity": 0, "occlusion": "none"})"});
            const Image zero = render(aov, kWidth, kHeight);
            float brightest = 0.0f;
            float largest = 0.0f;
            int pixels = 0;
            for (size_t i = 0; i < ids.texels.size(); ++i) {
                if (std::lround(ids.texels[i].r) < 1) continue;  // the background: the skybox draws it black
                ++pixels;
                for (int c = 0; c < 3; ++c) {
                    brightest = std::max(brightest, none.texels[i][c]);
                    largest = std::max(largest, std::abs(none.texels[i][c] - zero.texels[i][c]));
                }
            }
            ASSERT_GT(pixels, 1000) << setting;
            ASSERT_GT(brightest, 0.0f) << setting;
            std::printf("%s, AOV %d: environment of intensity 0 against none, largest difference %.3g of %.3g\n",
                        setting, int(aov), largest, brightest);
            EXPECT_LE(largest, 1e-5f * brightest) << setting << " AOV " << int(aov);
        }
    }
}
