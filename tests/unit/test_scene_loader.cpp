// Scene files: parsing, defaults, the sceneToJson round trip, error messages,
// robustness against truncated and mutated input, and the object-to-world
// transform.

#include "scene/SceneLoader.h"
#include "sss/BurleyProfile.h"

#include "FuzzSupport.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

namespace dermis {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScenePath = "content/scenes/full.json";

// Every key of the format with a non-default value.
constexpr const char* kFullScene = R"({
  "camera": {"position_m": [0.1, 0.2, 0.9], "target_m": [0, 0.05, 0], "up": [0, 1, 0.1],
             "vertical_fov_deg": 25, "near_m": 0.02, "far_m": 12.5},
  "lights": [
    {"type": "directional", "direction": [0, 0, -2], "colour": [1, 0.9, 0.8], "intensity": 3, "shadow": false},
    {"type": "spot", "position_m": [1, 2, 3], "direction": [1, 1, 0], "colour": [0.5, 0.5, 1],
     "intensity": 12.25, "spot_inner_deg": 10, "spot_outer_deg": 15},
    {"type": "point", "position_m": [-1, 0.5, 2], "intensity": 0}
  ],
  "characters": [
    {"name": "lee", "transform": {"translation_m": [0.3, -0.1, 0], "rotation_deg": [-90, 45, 5], "scale": 1.5},
     "mesh": {"gltf": "../meshes/lee.glb"}, "metres_per_unit": 0.01,
     "material": {"albedo_map": "/abs/albedo.png", "normal_map": "maps/normal.png", "flip_v": true,
                  "procedural": false, "albedo": [0.7, 0.5, 0.4], "roughness": 0.35, "rho_s": 0.2,
                  "profile": "marble"},
     "ssao": {"radius_m": 0.03, "samples": 64}},
    {"name": "head", "mesh": {"procedural": "head"}, "material": {"procedural": true, "profile": "none"}}
  ],
  "background": {"colour": [0.1, 0.2, 0.3]},
  "settings": {"exposure": 1.5, "ambient": [0.01, 0.02, 0.03], "energy_conservation": false,
               "shadow": {"map_size": 2048, "bias_constant_m": 0.001, "bias_slope_texels": 1.5, "filter": "poisson"},
               "sss": {"enabled": false, "variant": "lcb", "blur": "control", "taps": 13, "bilateral_depth_mm": 2.5,
                       "control_depth_scale_per_mm": 0.75, "gaussians": 4, "width_scale": 1.25, "min_width_px": 0.25,
                       "mix": 0.3, "lean_moment_width_mm": 1.5},
               "transmittance": {"enabled": false, "shrink_mm": 0.5, "strength": 2},
               "ssao": {"enabled": false, "samples": 32, "radius_m": 0.05, "strength": 0.8, "blur": false},
               "mode": "ts",
               "ts": {"taps": 9, "min_size": 128, "max_size": 1024, "tsm": true, "tsm_strength": 0.5,
                      "seam_blend": 1.5}}
})";

#define EXPECT_VEC3_EQ(a, b)                \
    do {                                    \
        EXPECT_EQ((a).x, (b).x) << #a ".x"; \
        EXPECT_EQ((a).y, (b).y) << #a ".y"; \
        EXPECT_EQ((a).z, (b).z) << #a ".z"; \
    } while (false)

#define EXPECT_VEC3_NEAR(a, b, tolerance)                \
    do {                                                 \
        EXPECT_NEAR((a).x, (b).x, tolerance) << #a ".x"; \
        EXPECT_NEAR((a).y, (b).y, tolerance) << #a ".y"; \
        EXPECT_NEAR((a).z, (b).z, tolerance) << #a ".z"; \
    } while (false)

void expectSceneEq(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.path, b.path);
    EXPECT_VEC3_EQ(a.camera.positionM, b.camera.positionM);
    EXPECT_VEC3_EQ(a.camera.targetM, b.camera.targetM);
    EXPECT_VEC3_EQ(a.camera.up, b.camera.up);
    EXPECT_EQ(a.camera.verticalFovDeg, b.camera.verticalFovDeg);
    EXPECT_EQ(a.camera.nearM, b.camera.nearM);
    EXPECT_EQ(a.camera.farM, b.camera.farM);
    ASSERT_EQ(a.lights.size(), b.lights.size());
    for (size_t i = 0; i < a.lights.size(); ++i) {
        SCOPED_TRACE("light " + std::to_string(i));
        const Light& x = a.lights[i];
        const Light& y = b.lights[i];
        EXPECT_EQ(x.type, y.type);
        EXPECT_VEC3_EQ(x.positionM, y.positionM);
        EXPECT_VEC3_EQ(x.direction, y.direction);
        EXPECT_VEC3_EQ(x.colour, y.colour);
        EXPECT_EQ(x.intensity, y.intensity);
        EXPECT_EQ(x.spotInnerDeg, y.spotInnerDeg);
        EXPECT_EQ(x.spotOuterDeg, y.spotOuterDeg);
        EXPECT_EQ(x.castsShadow, y.castsShadow);
        EXPECT_EQ(x.angularDiameterDeg, y.angularDiameterDeg);
        EXPECT_EQ(x.radiusM, y.radiusM);
    }
    ASSERT_EQ(a.characters.size(), b.characters.size());
    for (size_t i = 0; i < a.characters.size(); ++i) {
        SCOPED_TRACE("character " + std::to_string(i));
        const Character& x = a.characters[i];
        const Character& y = b.characters[i];
        EXPECT_EQ(x.name, y.name);
        EXPECT_VEC3_EQ(x.transform.translationM, y.transform.translationM);
        EXPECT_VEC3_EQ(x.transform.rotationDeg, y.transform.rotationDeg);
        EXPECT_EQ(x.transform.scale, y.transform.scale);
        EXPECT_EQ(x.mesh.procedural, y.mesh.procedural);
        EXPECT_EQ(x.mesh.gltfPath, y.mesh.gltfPath);
        EXPECT_EQ(x.metresPerUnit, y.metresPerUnit);
        EXPECT_EQ(x.material.albedoMap, y.material.albedoMap);
        EXPECT_EQ(x.material.normalMap, y.material.normalMap);
        EXPECT_EQ(x.material.flipV, y.material.flipV);
        EXPECT_EQ(x.material.procedural, y.material.procedural);
        EXPECT_VEC3_EQ(x.material.albedo, y.material.albedo);
        EXPECT_EQ(x.material.roughness, y.material.roughness);
        EXPECT_EQ(x.material.rhoS, y.material.rhoS);
        EXPECT_EQ(x.material.profile, y.material.profile);
        EXPECT_EQ(x.ssao.radiusM, y.ssao.radiusM);
        EXPECT_EQ(x.ssao.samples, y.ssao.samples);
    }
    EXPECT_VEC3_EQ(a.background.colour, b.background.colour);
    EXPECT_EQ(a.settings.exposure, b.settings.exposure);
    EXPECT_VEC3_EQ(a.settings.ambient, b.settings.ambient);
    EXPECT_EQ(a.settings.energyConservation, b.settings.energyConservation);
    EXPECT_EQ(a.settings.shadow.mapSize, b.settings.shadow.mapSize);
    EXPECT_EQ(a.settings.shadow.biasConstantM, b.settings.shadow.biasConstantM);
    EXPECT_EQ(a.settings.shadow.biasSlopeTexels, b.settings.shadow.biasSlopeTexels);
    EXPECT_EQ(a.settings.shadow.filter, b.settings.shadow.filter);
    const SssSettings& x = a.settings.sss;
    const SssSettings& y = b.settings.sss;
    EXPECT_EQ(x.enabled, y.enabled);
    EXPECT_EQ(x.variant, y.variant);
    EXPECT_EQ(x.blur, y.blur);
    EXPECT_EQ(x.taps, y.taps);
    EXPECT_EQ(x.bilateralDepthMm, y.bilateralDepthMm);
    EXPECT_EQ(x.controlDepthScalePerMm, y.controlDepthScalePerMm);
    EXPECT_EQ(x.gaussians, y.gaussians);
    EXPECT_EQ(x.widthScale, y.widthScale);
    EXPECT_EQ(x.minWidthPx, y.minWidthPx);
    EXPECT_EQ(x.mix, y.mix);
    EXPECT_EQ(a.settings.transmittance.enabled, b.settings.transmittance.enabled);
    EXPECT_EQ(a.settings.transmittance.shrinkMm, b.settings.transmittance.shrinkMm);
    EXPECT_EQ(a.settings.transmittance.strength, b.settings.transmittance.strength);
    EXPECT_EQ(a.settings.ssao.enabled, b.settings.ssao.enabled);
    EXPECT_EQ(a.settings.ssao.samples, b.settings.ssao.samples);
    EXPECT_EQ(a.settings.ssao.radiusM, b.settings.ssao.radiusM);
    EXPECT_EQ(a.settings.ssao.strength, b.settings.ssao.strength);
    EXPECT_EQ(a.settings.ssao.blur, b.settings.ssao.blur);
    EXPECT_EQ(a.settings.mode, b.settings.mode);
    EXPECT_EQ(a.settings.ts.taps, b.settings.ts.taps);
    EXPECT_EQ(a.settings.ts.minSize, b.settings.ts.minSize);
    EXPECT_EQ(a.settings.ts.maxSize, b.settings.ts.maxSize);
    EXPECT_EQ(a.settings.ts.tsm, b.settings.ts.tsm);
    EXPECT_EQ(a.settings.ts.tsmStrength, b.settings.ts.tsmStrength);
    EXPECT_EQ(a.settings.ts.seamBlend, b.settings.ts.seamBlend);
}

// The error text for a scene that must fail; "" (and a test failure) if it loads.
std::string errorOf(const std::string& json) {
    const Result<Scene> scene = parseScene(json, "x.json");
    EXPECT_FALSE(scene.ok()) << "accepted: " << json;
    if (scene.ok()) {
        return "";
    }
    EXPECT_EQ(scene.error().where, "x.json");
    EXPECT_EQ(scene.error().what.find('\n'), std::string::npos) << scene.error().what;
    return scene.error().what;
}

// A character with the given JSON members, inside an otherwise empty scene.
std::string withCharacter(const std::string& members) {
    return R"({"characters": [{)" + members + "}]}";
}

std::string withLight(const std::string& members) {
    return R"({"lights": [{)" + members + "}]}";
}

// For inputs that may or may not be valid: never crash, and every outcome is
// well formed. An accepted scene must also survive the round trip.
void expectWellFormedOutcome(const std::string& text) {
    const Result<Scene> scene = parseScene(text, "fuzz.json");
    if (!scene.ok()) {
        EXPECT_EQ(scene.error().where, "fuzz.json");
        EXPECT_FALSE(scene.error().what.empty());
        EXPECT_EQ(scene.error().what.find('\n'), std::string::npos) << scene.error().what;
        return;
    }
    const Result<Scene> again = parseScene(sceneToJson(*scene), "fuzz.json");
    ASSERT_TRUE(again.ok()) << again.error().message() << "\nfrom: " << text;
    expectSceneEq(*scene, *again);
}

class TempDir {
public:
    TempDir() {
        mPath = fs::temp_directory_path() / ("dermis_scene_test_" + std::to_string(std::random_device{}()));
        fs::create_directories(mPath / "scenes");
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(mPath, ec);
    }
    const fs::path& path() const { return mPath; }

private:
    fs::path mPath;
};

TEST(SceneLoader, FullSceneParsesIntoExpectedValues) {
    const Result<Scene> result = parseScene(kFullScene, kScenePath);
    ASSERT_TRUE(result.ok()) << result.error().message();
    const Scene& s = *result;
    EXPECT_EQ(s.path, kScenePath);

    EXPECT_VEC3_EQ(s.camera.positionM, glm::vec3(0.1f, 0.2f, 0.9f));
    EXPECT_VEC3_EQ(s.camera.targetM, glm::vec3(0.0f, 0.05f, 0.0f));
    // up is stored at unit length (a float lookAt of a 1e-30 or 3e38 long one under- or overflowed).
    EXPECT_VEC3_EQ(s.camera.up, glm::vec3(glm::normalize(glm::dvec3(0.0, 1.0, 0.1))));
    EXPECT_EQ(s.camera.verticalFovDeg, 25.0f);
    EXPECT_EQ(s.camera.nearM, 0.02f);
    EXPECT_EQ(s.camera.farM, 12.5f);

    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_VEC3_EQ(s.lights[0].direction, glm::vec3(0.0f, 0.0f, -1.0f));  // normalised
    EXPECT_VEC3_EQ(s.lights[0].colour, glm::vec3(1.0f, 0.9f, 0.8f));
    EXPECT_EQ(s.lights[0].intensity, 3.0f);
    EXPECT_FALSE(s.lights[0].castsShadow);
    EXPECT_EQ(s.lights[1].type, LightType::Spot);
    EXPECT_VEC3_EQ(s.lights[1].positionM, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_VEC3_NEAR(s.lights[1].direction, glm::vec3(std::sqrt(0.5f), std::sqrt(0.5f), 0.0f), 1e-7);
    EXPECT_EQ(s.lights[1].intensity, 12.25f);
    EXPECT_EQ(s.lights[1].spotInnerDeg, 10.0f);
    EXPECT_EQ(s.lights[1].spotOuterDeg, 15.0f);
    EXPECT_TRUE(s.lights[1].castsShadow);
    EXPECT_EQ(s.lights[2].type, LightType::Point);
    EXPECT_VEC3_EQ(s.lights[2].positionM, glm::vec3(-1.0f, 0.5f, 2.0f));
    EXPECT_EQ(s.lights[2].intensity, 0.0f);

    ASSERT_EQ(s.characters.size(), 2u);
    const Character& lee = s.characters[0];
    EXPECT_EQ(lee.name, "lee");
    EXPECT_VEC3_EQ(lee.transform.translationM, glm::vec3(0.3f, -0.1f, 0.0f));
    EXPECT_VEC3_EQ(lee.transform.rotationDeg, glm::vec3(-90.0f, 45.0f, 5.0f));
    EXPECT_EQ(lee.transform.scale, 1.5f);
    EXPECT_EQ(lee.mesh.gltfPath, "content/meshes/lee.glb");  // relative to the scene file
    EXPECT_EQ(lee.mesh.procedural, "");
    EXPECT_EQ(lee.metresPerUnit, 0.01f);
    EXPECT_EQ(lee.material.albedoMap, "/abs/albedo.png");  // absolute: unchanged
    EXPECT_EQ(lee.material.normalMap, "content/scenes/maps/normal.png");
    EXPECT_TRUE(lee.material.flipV);
    EXPECT_FALSE(lee.material.procedural);
    EXPECT_VEC3_EQ(lee.material.albedo, glm::vec3(0.7f, 0.5f, 0.4f));
    EXPECT_EQ(lee.material.roughness, 0.35f);
    EXPECT_EQ(lee.material.rhoS, 0.2f);
    EXPECT_EQ(lee.material.profile, "marble");
    EXPECT_EQ(lee.ssao.radiusM, 0.03f);
    EXPECT_EQ(lee.ssao.samples, 64);

    const Character& head = s.characters[1];
    EXPECT_EQ(head.name, "head");
    EXPECT_EQ(head.mesh.procedural, "head");
    EXPECT_EQ(head.mesh.gltfPath, "");
    EXPECT_TRUE(head.material.procedural);
    EXPECT_EQ(head.material.profile, "none");
    EXPECT_EQ(head.material.albedoMap, "");  // empty stays empty, not the scene directory
    EXPECT_EQ(head.ssao.radiusM, 0.0f);      // 0: the settings' radius and sample count
    EXPECT_EQ(head.ssao.samples, 0);

    EXPECT_VEC3_EQ(s.background.colour, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(s.settings.exposure, 1.5f);
    EXPECT_VEC3_EQ(s.settings.ambient, glm::vec3(0.01f, 0.02f, 0.03f));
    EXPECT_FALSE(s.settings.energyConservation);
    EXPECT_EQ(s.settings.shadow.mapSize, 2048);
    EXPECT_EQ(s.settings.shadow.biasConstantM, 0.001f);
    EXPECT_EQ(s.settings.shadow.biasSlopeTexels, 1.5f);
    EXPECT_EQ(s.settings.shadow.filter, ShadowFilter::Poisson);
    const SssSettings& sss = s.settings.sss;
    EXPECT_FALSE(sss.enabled);
    EXPECT_EQ(sss.variant, SssVariant::Lcb);
    EXPECT_EQ(sss.blur, SssBlur::Control);
    EXPECT_EQ(sss.taps, 13);
    EXPECT_EQ(sss.bilateralDepthMm, 2.5f);
    EXPECT_EQ(sss.controlDepthScalePerMm, 0.75f);
    EXPECT_EQ(sss.gaussians, 4);
    EXPECT_EQ(sss.widthScale, 1.25f);
    EXPECT_EQ(sss.minWidthPx, 0.25f);
    EXPECT_EQ(sss.mix, 0.3f);
    EXPECT_FALSE(s.settings.transmittance.enabled);
    EXPECT_EQ(s.settings.transmittance.shrinkMm, 0.5f);
    EXPECT_EQ(s.settings.transmittance.strength, 2.0f);
    const SsaoSettings& ssao = s.settings.ssao;
    EXPECT_FALSE(ssao.enabled);
    EXPECT_EQ(ssao.samples, 32);
    EXPECT_EQ(ssao.radiusM, 0.05f);
    EXPECT_EQ(ssao.strength, 0.8f);
    EXPECT_FALSE(ssao.blur);
}

// kFullScene must exercise every field: a field left at its default would let
// a writer that forgets it pass the round trip.
TEST(SceneLoader, FullSceneSetsEverySettingAwayFromItsDefault) {
    const Result<Scene> result = parseScene(kFullScene, kScenePath);
    ASSERT_TRUE(result.ok()) << result.error().message();
    const RenderSettings& s = result->settings;
    const RenderSettings d;
    EXPECT_NE(s.exposure, d.exposure);
    EXPECT_NE(s.ambient, d.ambient);
    EXPECT_NE(s.energyConservation, d.energyConservation);
    EXPECT_NE(s.shadow.mapSize, d.shadow.mapSize);
    EXPECT_NE(s.shadow.biasConstantM, d.shadow.biasConstantM);
    EXPECT_NE(s.shadow.biasSlopeTexels, d.shadow.biasSlopeTexels);
    EXPECT_NE(s.shadow.filter, d.shadow.filter);
    EXPECT_NE(s.sss.enabled, d.sss.enabled);
    EXPECT_NE(s.sss.variant, d.sss.variant);
    EXPECT_NE(s.sss.blur, d.sss.blur);
    EXPECT_NE(s.sss.taps, d.sss.taps);
    EXPECT_NE(s.sss.bilateralDepthMm, d.sss.bilateralDepthMm);
    EXPECT_NE(s.sss.controlDepthScalePerMm, d.sss.controlDepthScalePerMm);
    EXPECT_NE(s.sss.gaussians, d.sss.gaussians);
    EXPECT_NE(s.sss.widthScale, d.sss.widthScale);
    EXPECT_NE(s.sss.minWidthPx, d.sss.minWidthPx);
    EXPECT_NE(s.sss.mix, d.sss.mix);
    EXPECT_NE(s.sss.leanMomentWidthMm, d.sss.leanMomentWidthMm);
    EXPECT_NE(s.transmittance.enabled, d.transmittance.enabled);
    EXPECT_NE(s.transmittance.shrinkMm, d.transmittance.shrinkMm);
    EXPECT_NE(s.transmittance.strength, d.transmittance.strength);
    EXPECT_NE(s.ssao.enabled, d.ssao.enabled);
    EXPECT_NE(s.ssao.samples, d.ssao.samples);
    EXPECT_NE(s.ssao.radiusM, d.ssao.radiusM);
    EXPECT_NE(s.ssao.strength, d.ssao.strength);
    EXPECT_NE(s.ssao.blur, d.ssao.blur);
    EXPECT_NE(s.mode, d.mode);
    EXPECT_NE(s.ts.taps, d.ts.taps);
    EXPECT_NE(s.ts.minSize, d.ts.minSize);
    EXPECT_NE(s.ts.maxSize, d.ts.maxSize);
    EXPECT_NE(s.ts.tsm, d.ts.tsm);
    EXPECT_NE(s.ts.tsmStrength, d.ts.tsmStrength);
    EXPECT_NE(s.ts.seamBlend, d.ts.seamBlend);
    const CharacterSsao defaultSsao;
    EXPECT_NE(result->characters[0].ssao.radiusM, defaultSsao.radiusM);
    EXPECT_NE(result->characters[0].ssao.samples, defaultSsao.samples);
}

TEST(SceneLoader, AbsentKeysTakeTheStructDefaults) {
    const Result<Scene> empty = parseScene("{}", "empty.json");
    ASSERT_TRUE(empty.ok()) << empty.error().message();
    Scene expected;
    expected.path = "empty.json";
    expectSceneEq(*empty, expected);

    const Result<Scene> minimal = parseScene(
        R"({"lights": [{}], "characters": [{"mesh": {"procedural": "sphere"}, "ssao": {}}], "camera": {},
            "background": {}, "settings": {"shadow": {}, "sss": {}, "transmittance": {}, "ssao": {}}})",
        "minimal.json");
    ASSERT_TRUE(minimal.ok()) << minimal.error().message();
    expected.path = "minimal.json";
    expected.lights.emplace_back();
    expected.characters.emplace_back();
    expected.characters[0].mesh.procedural = "sphere";
    expectSceneEq(*minimal, expected);
}

TEST(SceneLoader, SceneWithoutCharactersIsValid) {
    const Result<Scene> scene = parseScene(R"({"characters": [], "lights": []})", "bare.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_TRUE(scene->characters.empty());
    EXPECT_TRUE(scene->lights.empty());
}

TEST(SceneLoader, IntegralSettingsAcceptIntegralNumbersOnly) {
    const Result<Scene> scene = parseScene(
        R"({"settings": {"shadow": {"map_size": 512.0}, "sss": {"taps": 7.0}, "ssao": {"samples": 8.0}}})", "x.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->settings.shadow.mapSize, 512);
    EXPECT_EQ(scene->settings.sss.taps, 7);
    EXPECT_EQ(scene->settings.ssao.samples, 8);
    EXPECT_EQ(errorOf(R"({"settings": {"shadow": {"map_size": 512.5}}})"),
              "/settings/shadow/map_size: expected an integer, got 512.5");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"taps": 9.5}}})"), "/settings/sss/taps: expected an integer, got 9.5");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"gaussians": "6"}}})"),
              "/settings/sss/gaussians: expected an integer, got a string");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "ssao": {"samples": 16.5})")),
              "/characters/0/ssao/samples: expected an integer, got 16.5");
}

TEST(SceneLoader, ProfileAndProceduralMeshNamesAreCheckedWithTheirKey) {
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"profile": "custom"})")),
              "/characters/0/material/profile: unknown diffusion profile \"custom\" (known: skin, marble or none)");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "cube"})")),
              "/characters/0/mesh/procedural: unknown procedural mesh \"cube\" (known: head, nodding_head, plane, sphere or wedge)");
    // Every name the engine knows loads, "none" (opaque) included.
    for (const std::string profile : {"skin", "marble", "none"}) {
        const std::string members = "\"mesh\": {\"procedural\": \"sphere\"}, \"material\": {\"profile\": \"" + profile + "\"}";
        EXPECT_TRUE(parseScene(withCharacter(members), "x.json").ok()) << profile;
    }
}

TEST(SceneLoader, SssTapsAreOddAndWithinRange) {
    for (const int taps : {3, 5, 9, 31, 33}) {
        const Result<Scene> scene =
            parseScene(R"({"settings": {"sss": {"taps": )" + std::to_string(taps) + "}}}", "x.json");
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        EXPECT_EQ(scene->settings.sss.taps, taps);
    }
    for (const int taps : {-3, 0, 1, 2, 4, 10, 32, 34, 35}) {
        EXPECT_EQ(errorOf(R"({"settings": {"sss": {"taps": )" + std::to_string(taps) + "}}}"),
                  "/settings/sss/taps: must be an odd number of taps in [3, 33], got " + std::to_string(taps));
    }
}

TEST(SceneLoader, CharacterSsaoSamplesAreZeroOrInRange) {
    for (const int samples : {0, 8, 64, 128}) {
        const Result<Scene> scene = parseScene(
            withCharacter(R"("mesh": {"procedural": "head"}, "ssao": {"samples": )" + std::to_string(samples) + "}"),
            "x.json");
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        EXPECT_EQ(scene->characters[0].ssao.samples, samples);
    }
    for (const int samples : {-8, 1, 7, 129}) {
        EXPECT_EQ(
            errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "ssao": {"samples": )" +
                                  std::to_string(samples) + "}")),
            "/characters/0/ssao/samples: must be 0 (use settings.ssao.samples) or in [8, 128], got " +
                std::to_string(samples));
    }
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "ssao": {"radius_m": -0.01})")),
              "/characters/0/ssao/radius_m: must be >= 0, got -0.01");
}

TEST(SceneLoader, LoadsFromDiskAndResolvesPathsFromTheFilesDirectory) {
    TempDir dir;
    const fs::path file = dir.path() / "scenes" / "one.json";
    std::ofstream(file) << withCharacter(R"("mesh": {"gltf": "../meshes/m.glb"}, "material": {"albedo_map": "a.png"})");
    const Result<Scene> scene = loadScene(file.string());
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->path, file.string());
    EXPECT_EQ(fs::path(scene->characters[0].mesh.gltfPath), dir.path() / "meshes" / "m.glb");
    EXPECT_EQ(fs::path(scene->characters[0].material.albedoMap), dir.path() / "scenes" / "a.png");
}

// The example in the format manual must stay a valid scene.
TEST(SceneLoader, ManualExampleParses) {
    const std::string manual = std::string(DERMIS_SOURCE_CONTENT_DIR) + "/scenes/README.md";
    std::ifstream file(manual);
    ASSERT_TRUE(file) << manual;
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    const size_t begin = text.find("```json\n");
    ASSERT_NE(begin, std::string::npos);
    const size_t end = text.find("```", begin + 8);
    ASSERT_NE(end, std::string::npos);
    const Result<Scene> scene = parseScene(text.substr(begin + 8, end - begin - 8), "content/scenes/example.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->lights.size(), 2u);
    ASSERT_EQ(scene->characters.size(), 2u);
    EXPECT_EQ(scene->characters[1].mesh.gltfPath, "content/meshes/lee.glb");
    EXPECT_EQ(scene->characters[1].metresPerUnit, 0.01f);
    EXPECT_EQ(scene->characters[1].ssao.samples, 32);
    EXPECT_EQ(scene->settings.shadow.mapSize, 2048);
    EXPECT_EQ(scene->settings.shadow.filter, ShadowFilter::Poisson);
    EXPECT_EQ(scene->settings.sss.taps, 13);
    EXPECT_EQ(scene->settings.ssao.strength, 0.8f);
}

// Every key the writer emits must be documented in the manual's tables.
TEST(SceneLoader, ManualDocumentsEveryKey) {
    const std::string manual = std::string(DERMIS_SOURCE_CONTENT_DIR) + "/scenes/README.md";
    std::ifstream file(manual);
    ASSERT_TRUE(file) << manual;
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    Scene scene;
    scene.lights.emplace_back();
    scene.characters.emplace_back();
    scene.characters[0].mesh.procedural = "head";
    // Names the file chooses (a glTF material, a user profile) are keys too, but not the manual's.
    const std::vector<std::string> names = {"Cloth", "wax"};
    scene.characters[0].materials[names[0]] = Material{};
    scene.profiles.push_back(*DiffusionProfile::create(names[1], {{1.0f, glm::vec3(1.0f)}}));
    const std::string written = sceneToJson(scene);
    size_t keys = 0;
    for (size_t at = written.find("\n"); at != std::string::npos; at = written.find("\n", at + 1)) {
        const size_t open = written.find_first_not_of(' ', at + 1);
        if (open == std::string::npos || written[open] != '"') {
            continue;
        }
        const std::string key = written.substr(open + 1, written.find('"', open + 1) - open - 1);
        if (std::find(names.begin(), names.end(), key) != names.end()) continue;
        const bool documented = text.find("| `" + key + "` |") != std::string::npos ||
                                text.find("### `" + key + "` (") != std::string::npos;
        EXPECT_TRUE(documented) << "undocumented key " << key;
        ++keys;
    }
    EXPECT_GT(keys, 50u);
}

TEST(SceneWriter, RoundTripReproducesEveryField) {
    const Result<Scene> original = parseScene(kFullScene, kScenePath);
    ASSERT_TRUE(original.ok()) << original.error().message();
    const std::string text = sceneToJson(*original);
    const Result<Scene> again = parseScene(text, kScenePath);
    ASSERT_TRUE(again.ok()) << again.error().message() << "\n" << text;
    expectSceneEq(*original, *again);
    EXPECT_EQ(sceneToJson(*again), text);  // stable: writing again changes nothing
    // Paths are written relative to the scene file, as they were read.
    EXPECT_NE(text.find("\"../meshes/lee.glb\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"maps/normal.png\""), std::string::npos) << text;
}

TEST(SceneWriter, RoundTripKeepsAwkwardFloatsAndDefaults) {
    Scene scene;
    scene.path = "deep/dir/awkward.json";
    scene.camera.positionM = glm::vec3(1.0f / 3.0f, 1e-7f, -12345.6789f);
    scene.camera.nearM = 0.1f;
    scene.camera.farM = 9999.99f;  // as far as 1e5 x near_m allows
    Light light;
    light.type = LightType::Spot;
    light.direction = glm::normalize(glm::vec3(0.3f, -0.7f, 0.2f));
    light.colour = glm::vec3(16777217.0f, 0.1f, 1e-30f);
    light.spotInnerDeg = 30.0f;
    light.spotOuterDeg = 30.0f;
    light.angularDiameterDeg = 0.53f;
    light.radiusM = 1.0f / 3.0f;
    scene.lights = {light, Light{}};
    Character character;
    character.name = "na\"me/with\\odd\tchars \xc3\xa9 [1,  2]\\";
    character.mesh.gltfPath = "deep/meshes/x.gltf";
    character.material.normalMap = "/absolute/n.png";
    character.metresPerUnit = 0.0254f;
    character.transform.rotationDeg = glm::vec3(-179.99f, 0.001f, 720.0f);
    scene.characters = {character};
    scene.settings.shadow.mapSize = 64;
    scene.settings.shadow.biasConstantM = 1e-7f;
    scene.settings.sss.mix = 1.0f / 3.0f;
    scene.settings.sss.taps = 33;
    scene.settings.ssao.radiusM = 0.1f;
    scene.characters[0].ssao.radiusM = 2.0f / 3.0f;

    const std::string text = sceneToJson(scene);
    const Result<Scene> again = parseScene(text, scene.path);
    ASSERT_TRUE(again.ok()) << again.error().message() << "\n" << text;
    expectSceneEq(scene, *again);
    EXPECT_NE(text.find("\"../meshes/x.gltf\""), std::string::npos) << text;

    const Scene defaults;
    const Result<Scene> defaultsAgain = parseScene(sceneToJson(defaults), "");
    ASSERT_TRUE(defaultsAgain.ok()) << defaultsAgain.error().message();
    expectSceneEq(defaults, *defaultsAgain);
}

TEST(SceneWriter, WritesShortestDecimalsWithTwoSpaceIndent) {
    const std::string text = sceneToJson(Scene{});
    EXPECT_NE(text.find("\n  \"camera\": {\n    \"position_m\": ["), std::string::npos) << text;
    EXPECT_NE(text.find("\"near_m\": 0.05,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"position_m\": [0.0, 0.0, 1.0],"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.0500000"), std::string::npos) << text;
}

TEST(SceneWriter, WritesSettingsAsNestedGroups) {
    const std::string text = sceneToJson(Scene{});
    EXPECT_NE(text.find("\"energy_conservation\": true,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"shadow\": {\n      \"map_size\": 1024,"), std::string::npos) << text;
    EXPECT_NE(text.find("\"filter\": \"pcss\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"sss\": {\n      \"enabled\": true,\n      \"variant\": \"lbb\",\n      \"blur\": \"variant\",\n      \"technique\": \"gaussians\","),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("\"quality\": {\n      \"error_budget\": 0.0,\n      \"table\": \"\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"transmittance\": {"), std::string::npos) << text;
    EXPECT_NE(text.find("\"ssao\": {\n      \"enabled\": true,\n      \"samples\": 16,"), std::string::npos) << text;
    EXPECT_EQ(text.find("shadow_map_size"), std::string::npos) << text;
}

TEST(SceneLoader, MissingFileNamesTheFile) {
    const std::string path = "/nonexistent/dermis/missing_scene.json";
    const Result<Scene> scene = loadScene(path);
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().where, path);
    EXPECT_EQ(scene.error().what, "cannot open scene file: No such file or directory");
    EXPECT_NE(scene.error().message().find("missing_scene.json"), std::string::npos);
}

TEST(SceneLoader, FifoIsRefusedWithoutBlocking) {
    const std::string path = (std::filesystem::temp_directory_path() / ("dermis_scene_fifo_" + std::to_string(::getpid()))).string();
    ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
    const Result<Scene> scene = loadScene(path);  // opening a FIFO for reading would wait for a writer
    std::filesystem::remove(path);
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().where, path);
    EXPECT_EQ(scene.error().what, "cannot open scene file: it is not a regular file");
}

TEST(SceneLoader, MalformedJsonReportsFileLineAndColumn) {
    TempDir dir;
    const fs::path file = dir.path() / "broken.json";
    std::ofstream(file) << "{\n  \"camera\": {\n    \"near_m\": 0.1,\n  }\n}\n";
    const Result<Scene> scene = loadScene(file.string());
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().where, file.string());
    EXPECT_NE(scene.error().what.find("line 4, column 3"), std::string::npos) << scene.error().what;
    EXPECT_EQ(scene.error().what.find("json.exception"), std::string::npos) << scene.error().what;
    EXPECT_EQ(scene.error().what.find('\n'), std::string::npos);

    EXPECT_EQ(errorOf("{\n  \"camera\": {},\n  \"lights\": [],\n}"),
              "parse error at line 4, column 1: syntax error while parsing object key - unexpected '}'; "
              "expected string literal");
    EXPECT_NE(errorOf("").find("line 1"), std::string::npos);
    EXPECT_NE(errorOf("{} trailing").find("line 1"), std::string::npos);
    EXPECT_NE(errorOf("{\"a\": 1 // comment\n}").find("line 1"), std::string::npos);
}

TEST(SceneLoader, UnknownKeyIsNamedWithTheKnownOnes) {
    EXPECT_EQ(errorOf(R"({"background": {"colr": [1, 1, 1]}})"),
              "/background/colr: unknown key \"colr\" (known: colour)");
    EXPECT_EQ(errorOf(R"({"camra": {}})"),
              "/camra: unknown key \"camra\": did you mean \"camera\"? (known: camera, lights, characters, profiles, background, environment and settings)");
    EXPECT_EQ(
        errorOf(R"({"lights": [{}, {"colour": [1, 1, 1], "power": 2}]})").rfind("/lights/1/power: unknown key", 0), 0u);
    // Keys with pointer syntax in them are escaped.
    EXPECT_EQ(errorOf(R"({"a/b~c": 1})").rfind("/a~1b~0c: unknown key \"a/b~c\"", 0), 0u);
}

TEST(SceneLoader, WrongTypesAreNamed) {
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": "0.1"}})"), "/camera/near_m: expected a number, got a string");
    EXPECT_EQ(errorOf(R"({"camera": []})"), "/camera: expected an object, got an array");
    EXPECT_EQ(errorOf(R"({"lights": {}})"), "/lights: expected an array, got an object");
    EXPECT_EQ(errorOf(R"({"lights": [3]})"), "/lights/0: expected an object, got a number");
    EXPECT_EQ(errorOf(withLight(R"("shadow": 1)")), "/lights/0/shadow: expected true or false, got a number");
    EXPECT_EQ(errorOf(withCharacter(R"("name": null, "mesh": {"procedural": "head"})")),
              "/characters/0/name: expected a string, got null");
    EXPECT_EQ(errorOf("[]"), "expected an object, got an array");
}

TEST(SceneLoader, VectorsAreThreeFiniteNumbers) {
    EXPECT_EQ(errorOf(R"({"camera": {"up": [0, 1]}})"), "/camera/up: expected an array of 3 numbers, got 2 elements");
    EXPECT_EQ(errorOf(R"({"camera": {"up": [0, 1, 0, 0]}})"),
              "/camera/up: expected an array of 3 numbers, got 4 elements");
    EXPECT_EQ(errorOf(R"({"camera": {"up": [0, "1", 0]}})"), "/camera/up/1: expected a number, got a string");
    EXPECT_EQ(errorOf(R"({"camera": {"up": 1}})"), "/camera/up: expected an array of 3 numbers, got a number");
    EXPECT_EQ(errorOf(R"({"background": {"colour": [0, -0.5, 0]}})"), "/background/colour/1: must be in [0, 1e+20], got -0.5");
}

TEST(SceneLoader, UnknownLightTypeListsTheAcceptedOnes) {
    const std::string what = errorOf(withLight(R"("type": "laser")"));
    EXPECT_NE(what.find("/lights/0/type"), std::string::npos);
    EXPECT_NE(what.find("laser"), std::string::npos);
    EXPECT_EQ(what, "/lights/0/type: unknown light type \"laser\" (expected directional, spot or point)");
    EXPECT_EQ(errorOf(R"({"settings": {"shadow": {"filter": "pcf"}}})"),
              "/settings/shadow/filter: unknown shadow filter \"pcf\" (expected pcf4x4, poisson or pcss)");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"blur": "gaussian"}}})"),
              "/settings/sss/blur: unknown SSS blur \"gaussian\" (expected variant, bilateral, control or fetch-only)");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"blur": 1}}})"), "/settings/sss/blur: expected a string, got a number");
}

// Vila Verde 2015's comparison: the variant picks the specular path and, unless
// `blur` names one, the blur (plan/SssVariant.h).
TEST(SceneLoader, SssVariantDefaultsToLeanBilateralAndAcceptsTheThree) {
    const Result<Scene> empty = parseScene("{}", kScenePath);
    ASSERT_TRUE(empty.ok());
    EXPECT_EQ(empty->settings.sss.variant, SssVariant::Lbb);
    EXPECT_EQ(empty->settings.sss.blur, SssBlur::Variant);
    for (const char* variant : {"c", "lcb", "lbb"}) {
        const Result<Scene> scene =
            parseScene(std::string(R"({"settings": {"sss": {"variant": ")") + variant + R"("}}})", kScenePath);
        ASSERT_TRUE(scene.ok()) << scene.error().message();
        EXPECT_EQ(kSssVariants.name(scene->settings.sss.variant), variant);
        const Result<Scene> again = parseScene(sceneToJson(*scene), kScenePath);
        ASSERT_TRUE(again.ok());
        EXPECT_EQ(again->settings.sss.variant, scene->settings.sss.variant);
    }
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"variant": "LBB"}}})"),
              "/settings/sss/variant: unknown SSS variant \"LBB\" (expected c, lcb or lbb)");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"variant": true}}})"),
              "/settings/sss/variant: expected a string, got a boolean");
}

TEST(SceneLoader, MeshNeedsExactlyOneSource) {
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head", "gltf": "a.glb"})")),
              "/characters/0/mesh: give exactly one of \"procedural\" and \"gltf\", not both");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {})")).rfind("/characters/0/mesh: missing mesh source", 0), 0u);
    EXPECT_EQ(errorOf(withCharacter(R"("name": "x")")), "/characters/0: missing required key \"mesh\"");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"gltf": ""})")), "/characters/0/mesh/gltf: must not be empty");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": ""})")),
              "/characters/0/mesh/procedural: must not be empty");
}

TEST(SceneLoader, OutOfRangeValuesAreRejected) {
    EXPECT_EQ(errorOf(withLight(R"("intensity": -1)")), "/lights/0/intensity: must be >= 0, got -1");
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 2, "far_m": 2}})"),
              "/camera/near_m: must be less than far_m (2), got 2");
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 0.5, "far_m": 0.1}})"),
              "/camera/near_m: must be less than far_m (0.1), got 0.5");
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 0}})"), "/camera/near_m: must be >= 1e-04, got 0");
    EXPECT_EQ(errorOf(R"({"camera": {"vertical_fov_deg": 180}})"),
              "/camera/vertical_fov_deg: must be in [1, 179], got 180");
    // The hostile values that rendered wrong images with exit 0 (core/Limits.h).
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 1e-5}})"), "/camera/near_m: must be >= 1e-04, got 1e-05");
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 0.01, "far_m": 2e38}})"),
              "/camera/far_m: must be at most 1e+05 x near_m (depth precision), got 2e+40 x");
    EXPECT_EQ(errorOf(R"({"camera": {"vertical_fov_deg": 1e-10}})"),
              "/camera/vertical_fov_deg: must be in [1, 179], got 1e-10");
    EXPECT_EQ(errorOf(R"({"settings": {"exposure": 1e20}})"), "/settings/exposure: must be in (0, 10000], got 1e+20");
    EXPECT_EQ(errorOf(R"({"camera": {"position_m": [1, 2, 3], "target_m": [1, 2, 3]}})"),
              "/camera/target_m: must be at least 1e-06 m from position_m (the camera needs a view direction)");
    EXPECT_EQ(errorOf(R"({"camera": {"position_m": [0, 2, 0], "target_m": [0, 0, 0]}})")
                  .rfind("/camera/up: must not be parallel", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"camera": {"up": [0, 0, 0]}})"), "/camera/up: must not be the zero vector");
    EXPECT_EQ(errorOf(withLight(R"("direction": [0, 0, 0])")), "/lights/0/direction: must not be the zero vector");
    EXPECT_EQ(errorOf(withLight(R"("spot_inner_deg": 40, "spot_outer_deg": 35)")),
              "/lights/0/spot_inner_deg: must be <= spot_outer_deg (35), got 40");
    EXPECT_EQ(errorOf(withLight(R"("spot_outer_deg": 90)")), "/lights/0/spot_outer_deg: must be in [0, 90), got 90");
    EXPECT_EQ(errorOf(withLight(R"("colour": [1, 1, -1])")), "/lights/0/colour/2: must be >= 0, got -1");
    EXPECT_EQ(errorOf(withLight(R"("angular_diameter_deg": 30)")),
              "/lights/0/angular_diameter_deg: must be in [0, 30), got 30");
    EXPECT_EQ(errorOf(withLight(R"("angular_diameter_deg": -0.5)")),
              "/lights/0/angular_diameter_deg: must be in [0, 30), got -0.5");
    EXPECT_EQ(errorOf(withLight(R"("radius_m": 1)")), "/lights/0/radius_m: must be in [0, 1), got 1");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "metres_per_unit": 0)")),
              "/characters/0/metres_per_unit: must be > 0, got 0");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "transform": {"scale": -1})")),
              "/characters/0/transform/scale: must be > 0, got -1");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"roughness": 0})")),
              "/characters/0/material/roughness: must be in (0, 1], got 0");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"rho_s": 1.5})")),
              "/characters/0/material/rho_s: must be in [0, 1], got 1.5");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"albedo": [0.5, 1.2, 0.5]})")),
              "/characters/0/material/albedo/1: must be in [0, 1], got 1.2");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"profile": ""})")),
              "/characters/0/material/profile: must not be empty");
    EXPECT_EQ(errorOf(R"({"settings": {"exposure": 0}})"), "/settings/exposure: must be in (0, 10000], got 0");
    EXPECT_EQ(errorOf(R"({"settings": {"ambient": [0, -1, 0]}})"), "/settings/ambient/1: must be in [0, 1e+20], got -1");
    // The float32 limits of core/Limits.h: the values the review found to
    // render black or blank are refused, the largest legal ones are read.
    EXPECT_EQ(errorOf(R"({"settings": {"ambient": [0, 3e20, 0]}})"), "/settings/ambient/1: must be in [0, 1e+20], got 3e+20");
    EXPECT_EQ(errorOf(R"({"background": {"colour": [2e20, 0, 0]}})"), "/background/colour/0: must be in [0, 1e+20], got 2e+20");
    EXPECT_EQ(errorOf(withLight(R"("colour": [3e38, 1, 1], "intensity": 3e38)")),
              "/lights/0/intensity: colour x intensity must be at most 1e+20 per channel (float range), got 9e+76");
    EXPECT_EQ(errorOf(withLight(R"("colour": [0.5, 2, 1], "intensity": 1e20)")),
              "/lights/0/intensity: colour x intensity must be at most 1e+20 per channel (float range), got 2e+20");
    EXPECT_TRUE(parseScene(withLight(R"("colour": [0.5, 1, 1], "intensity": 1e20)"), "x.json").ok());
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "metres_per_unit": 1e20, "transform": {"scale": 1e20})")),
              "/characters/0/metres_per_unit: transform.scale x metres_per_unit must be in [1e-06, 1e+06] metres per mesh "
              "unit, got 1e+40");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "metres_per_unit": 1e-4, "transform": {"scale": 0.001})")),
              "/characters/0/metres_per_unit: transform.scale x metres_per_unit must be in [1e-06, 1e+06] metres per mesh "
              "unit, got 1e-07");
    EXPECT_TRUE(parseScene(withCharacter(R"("mesh": {"procedural": "head"}, "metres_per_unit": 1e-3, "transform": {"scale": 1e-3})"),
                           "x.json")
                    .ok());
    // A positive value that rounds to 0 as a float is as bad as 0.
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 1e-60}})"), "/camera/near_m: must be >= 1e-04, got 1e-60");
}

// The camera values a probe found to crash the reference (Embree refused
// its rays) or render an empty frame, each refused by name or made safe:
// coordinates past kMaxWorldCoordinateM, a target 1e-30 m from the camera,
// an up vector 1e-30 or 1e20 long (stored at unit length: closed form).
TEST(SceneLoader, CameraVectorsThatOverflowAreRefusedOrNormalised) {
    EXPECT_EQ(errorOf(R"({"camera": {"position_m": [0, 0.03, 1e38]}})"),
              "/camera/position_m/2: must be in [-1e+05, 1e+05], got 1e+38");
    EXPECT_EQ(errorOf(R"({"camera": {"target_m": [-2e5, 0, 0]}})"), "/camera/target_m/0: must be in [-1e+05, 1e+05], got -2e+05");
    EXPECT_EQ(errorOf(withLight(R"("position_m": [0, 1e6, 0])")), "/lights/0/position_m/1: must be in [-1e+05, 1e+05], got 1e+06");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "transform": {"translation_m": [3e38, 0, 0]})")),
              "/characters/0/transform/translation_m/0: must be in [-1e+05, 1e+05], got 3e+38");
    EXPECT_EQ(errorOf(R"({"camera": {"position_m": [0, 0, 1e-30], "target_m": [0, 0, 0]}})"),
              "/camera/target_m: must be at least 1e-06 m from position_m (the camera needs a view direction)");
    for (const char* up : {"[0, 1e-30, 0]", "[0, 1e20, 0]", "[0, 3e38, 0]", "[0, 1e-40, 0]"}) {
        auto scene = parseScene(std::string(R"({"camera": {"up": )") + up + "}}", "x.json");
        ASSERT_TRUE(scene) << up << ": " << scene.error().message();
        EXPECT_EQ(scene->camera.up, glm::vec3(0.0f, 1.0f, 0.0f)) << up;
    }
    // Within the limits the scene is read as written.
    auto edge = parseScene(R"({"camera": {"position_m": [1e5, -1e5, 0], "target_m": [0, 0, 0], "up": [0, 0, 2]}})", "x.json");
    ASSERT_TRUE(edge) << edge.error().message();
    EXPECT_EQ(edge->camera.positionM, glm::vec3(1e5f, -1e5f, 0.0f));
    EXPECT_EQ(edge->camera.up, glm::vec3(0.0f, 0.0f, 1.0f));
}

// Bounds as the manual writes them hold for the floats they become: near_m
// 1e-4 (a float just below 1e-4), far / near of exactly 1e5 in decimals
// (100000.002 in floats); a ratio just past the limit names itself in full.
TEST(SceneLoader, DocumentedBoundsHoldForTheirFloats) {
    EXPECT_TRUE(parseScene(R"({"camera": {"near_m": 0.0001, "far_m": 10}})", "x.json").ok());
    EXPECT_TRUE(parseScene(R"({"camera": {"near_m": 1e-4, "far_m": 10}})", "x.json").ok());
    EXPECT_TRUE(parseScene(R"({"camera": {"near_m": 0.01, "far_m": 1000}})", "x.json").ok());
    EXPECT_TRUE(parseScene(R"({"camera": {"near_m": 0.001, "far_m": 100}})", "x.json").ok());
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 0.001, "far_m": 100.001}})"),
              "/camera/far_m: must be at most 1e+05 x near_m (depth precision), got 100001 x");
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 9.99e-5}})"), "/camera/near_m: must be >= 1e-04, got 9.99e-05");
    // width_scale: past 1e4 the screen-space blurs scattered nothing from 2e19 on.
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"width_scale": 2e19}}})"),
              "/settings/sss/width_scale: must be in [0, 10000], got 2e+19");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "material": {"width_scale": 1e30})")),
              "/characters/0/material/width_scale: must be in (0, 10000], got 1e+30");
    EXPECT_TRUE(parseScene(R"({"settings": {"sss": {"width_scale": 10000}}})", "x.json").ok());
}

TEST(SceneLoader, OutOfRangeSettingsAreRejected) {
    const auto settingsError = [](const std::string& group, const std::string& member) {
        return errorOf(R"({"settings": {")" + group + R"(": {)" + member + "}}}");
    };
    EXPECT_EQ(settingsError("shadow", R"("map_size": 32)"), "/settings/shadow/map_size: must be in [64, 8192], got 32");
    EXPECT_EQ(settingsError("shadow", R"("map_size": 10000)"),
              "/settings/shadow/map_size: must be in [64, 8192], got 10000");
    EXPECT_EQ(settingsError("shadow", R"("bias_constant_m": -0.001)"),
              "/settings/shadow/bias_constant_m: must be >= 0, got -0.001");
    EXPECT_EQ(settingsError("shadow", R"("bias_slope_texels": -0.5)"),
              "/settings/shadow/bias_slope_texels: must be >= 0, got -0.5");
    EXPECT_EQ(settingsError("sss", R"("bilateral_depth_mm": 0)"),
              "/settings/sss/bilateral_depth_mm: must be > 0, got 0");
    EXPECT_EQ(settingsError("sss", R"("control_depth_scale_per_mm": -1)"),
              "/settings/sss/control_depth_scale_per_mm: must be >= 0, got -1");
    EXPECT_EQ(settingsError("sss", R"("gaussians": 0)"), "/settings/sss/gaussians: must be in [1, 8], got 0");
    EXPECT_EQ(settingsError("sss", R"("gaussians": 9)"), "/settings/sss/gaussians: must be in [1, 8], got 9");
    EXPECT_EQ(settingsError("sss", R"("width_scale": -0.5)"), "/settings/sss/width_scale: must be in [0, 10000], got -0.5");
    EXPECT_EQ(settingsError("sss", R"("min_width_px": -1)"), "/settings/sss/min_width_px: must be >= 0, got -1");
    EXPECT_EQ(settingsError("sss", R"("mix": 1.5)"), "/settings/sss/mix: must be in [0, 1], got 1.5");
    EXPECT_EQ(settingsError("sss", R"("lean_moment_width_mm": -1)"), "/settings/sss/lean_moment_width_mm: must be >= 0, got -1");
    EXPECT_EQ(settingsError("sss", R"("mix": -0.1)"), "/settings/sss/mix: must be in [0, 1], got -0.1");
    EXPECT_EQ(settingsError("transmittance", R"("shrink_mm": -1)"),
              "/settings/transmittance/shrink_mm: must be >= 0, got -1");
    EXPECT_EQ(settingsError("transmittance", R"("strength": -2)"),
              "/settings/transmittance/strength: must be >= 0, got -2");
    EXPECT_EQ(settingsError("ssao", R"("samples": 7)"), "/settings/ssao/samples: must be in [8, 128], got 7");
    EXPECT_EQ(settingsError("ssao", R"("samples": 129)"), "/settings/ssao/samples: must be in [8, 128], got 129");
    EXPECT_EQ(settingsError("ssao", R"("radius_m": 0)"), "/settings/ssao/radius_m: must be > 0, got 0");
    EXPECT_EQ(settingsError("ssao", R"("strength": 1.01)"), "/settings/ssao/strength: must be in [0, 1], got 1.01");
    // The edges of closed ranges are accepted.
    const Result<Scene> edges = parseScene(
        R"({"settings": {"shadow": {"map_size": 8192, "bias_constant_m": 0, "bias_slope_texels": 0},
                         "sss": {"gaussians": 8, "width_scale": 0, "min_width_px": 0, "mix": 1,
                                 "control_depth_scale_per_mm": 0},
                         "transmittance": {"shrink_mm": 0, "strength": 0},
                         "ssao": {"samples": 128, "strength": 0}}})",
        "x.json");
    ASSERT_TRUE(edges.ok()) << edges.error().message();
    EXPECT_EQ(edges->settings.shadow.mapSize, 8192);
    EXPECT_EQ(edges->settings.sss.gaussians, 8);
    EXPECT_EQ(edges->settings.sss.mix, 1.0f);
    EXPECT_EQ(edges->settings.ssao.samples, 128);
}

TEST(SceneLoader, SettingsGroupsAreStrictObjects) {
    EXPECT_EQ(errorOf(R"({"settings": {"sss": []}})"), "/settings/sss: expected an object, got an array");
    EXPECT_EQ(errorOf(R"({"settings": {"shadow": 1024}})"), "/settings/shadow: expected an object, got a number");
    EXPECT_EQ(errorOf(R"({"settings": {"ssao": {"enabled": "yes"}}})"),
              "/settings/ssao/enabled: expected true or false, got a string");
    EXPECT_EQ(errorOf(R"({"settings": {"energy_conservation": 1}})"),
              "/settings/energy_conservation: expected true or false, got a number");
    EXPECT_EQ(errorOf(R"({"settings": {"transmittance": {"shrink": 1}}})"),
              "/settings/transmittance/shrink: unknown key \"shrink\" (known: enabled, shrink_mm, strength and thin_edges)");
    EXPECT_EQ(errorOf(R"({"settings": {"sss": {"width": 1}}})"),
              "/settings/sss/width: unknown key \"width\" (known: enabled, variant, blur, technique, taps, gaussians, separable_samples, "
              "disk_samples, bilateral_depth_mm, "
              "control_depth_scale_per_mm, width_scale, min_width_px, mix and lean_moment_width_mm)");
    EXPECT_EQ(errorOf(withCharacter(R"("mesh": {"procedural": "head"}, "ssao": {"radius": 1})")),
              "/characters/0/ssao/radius: unknown key \"radius\": did you mean \"radius_m\"? (known: radius_m and samples)");
    // The flat shadow keys of the first format are gone.
    EXPECT_EQ(errorOf(R"({"settings": {"shadow_map_size": 2048}})"),
              "/settings/shadow_map_size: unknown key \"shadow_map_size\" (known: exposure, tone_map, ambient, "
              "energy_conservation, cull_back_faces, mode, shadow, sss, transmittance, ssao, ts, quality and lod)");
}

TEST(SceneLoader, ModeAndTextureSpaceSettingsAreChecked) {
    const Result<Scene> scene = parseScene(R"({"settings": {"mode": "ts", "ts": {"min_size": 64, "max_size": 4096}}})",
                                           "x.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->settings.mode, SssMode::TextureSpace);
    EXPECT_EQ(scene->settings.ts.minSize, 64);
    EXPECT_EQ(scene->settings.ts.maxSize, 4096);
    EXPECT_EQ(errorOf(R"({"settings": {"mode": "texture"}})"),
              "/settings/mode: unknown SSS mode \"texture\" (expected ss or ts)");
    for (const int taps : {1, 2, 8, 35}) {
        EXPECT_EQ(errorOf(R"({"settings": {"ts": {"taps": )" + std::to_string(taps) + "}}}"),
                  "/settings/ts/taps: must be an odd number of taps in [3, 33], got " + std::to_string(taps));
    }
    for (const int size : {0, 32, 300, 8192}) {
        EXPECT_EQ(errorOf(R"({"settings": {"ts": {"max_size": )" + std::to_string(size) + "}}}"),
                  "/settings/ts/max_size: must be a power of two in [64, 4096], got " + std::to_string(size));
    }
    EXPECT_EQ(errorOf(R"({"settings": {"ts": {"min_size": 1024, "max_size": 512}}})"),
              "/settings/ts/min_size: must be <= max_size (512), got 1024");
    EXPECT_EQ(errorOf(R"({"settings": {"ts": {"tsm_strength": -1}}})"),
              "/settings/ts/tsm_strength: must be >= 0, got -1");
    EXPECT_EQ(errorOf(R"({"settings": {"ts": {"seam_blend": -0.5}}})"),
              "/settings/ts/seam_blend: must be >= 0, got -0.5");
    EXPECT_EQ(errorOf(R"({"settings": {"ts": {"tsm": 1}}})"), "/settings/ts/tsm: expected true or false, got a number");
}

TEST(SceneLoader, NumbersMustBeFiniteFloats) {
    EXPECT_EQ(errorOf(R"({"settings": {"exposure": 1e39}})"),
              "/settings/exposure: number 1e+39 is out of range for a 32-bit float");
    EXPECT_EQ(errorOf(R"({"camera": {"up": [0, 1e39, 0]}})"),
              "/camera/up/1: number 1e+39 is out of range for a 32-bit float");
    EXPECT_EQ(errorOf("{\n\"settings\": {\"exposure\": 1e999}}"), "line 2, column 26: /settings/exposure: number 1e999 is out of range (finite numbers reach about +-1.8e308)");
    EXPECT_EQ(errorOf("{\"lights\": [{}, {\"colour\": [1, -1e999, 1]}]}"), "line 1, column 32: /lights/1/colour/1: number -1e999 is out of range (finite numbers reach about +-1.8e308)");
    EXPECT_NE(errorOf(R"({"settings": {"exposure": NaN}})").find("line 1"), std::string::npos);
}

TEST(SceneLoader, DuplicateKeysAreErrors) {
    EXPECT_EQ(errorOf(R"({"camera": {"near_m": 0.1, "near_m": 0.2}})"), "/camera/near_m: duplicate key \"near_m\"");
    EXPECT_EQ(errorOf(R"({"lights": [{}, {"type": "spot", "type": "point"}]})"),
              "/lights/1/type: duplicate key \"type\"");
    EXPECT_EQ(errorOf(R"({"characters": [], "characters": []})"), "/characters: duplicate key \"characters\"");
}

TEST(SceneLoader, ArraySizesAreCapped) {
    std::string lights = R"({"lights": [)";
    for (int i = 0; i < 1024; ++i) {
        lights += i == 0 ? "{}" : ", {}";
    }
    const Result<Scene> atLimit = parseScene(lights + "]}", "x.json");
    ASSERT_TRUE(atLimit.ok()) << atLimit.error().message();
    EXPECT_EQ(atLimit->lights.size(), 1024u);
    EXPECT_EQ(errorOf(lights + ", {}]}"), "/lights: too many lights (1025; at most 1024)");
}

TEST(SceneLoader, DeepNestingAndHugeInputAreErrorsNotCrashes) {
    const std::string deep(200000, '[');
    EXPECT_EQ(errorOf(deep), "JSON nested deeper than 256 levels");
    EXPECT_EQ(errorOf(R"({"camera": {"up": )" + std::string(300, '[') + std::string(300, ']') + "}}"),
              "JSON nested deeper than 256 levels");
    EXPECT_EQ(errorOf(R"({"camera": {"up": [[[[[[[[1]]]]]]]]}})"),
              "/camera/up: expected an array of 3 numbers, got 1 elements");
    const std::string huge = "{\"characters\": [" + std::string(17u << 20, ' ') + "]}";
    EXPECT_NE(errorOf(huge).find("the limit is"), std::string::npos);
}

TEST(SceneLoader, InvalidUtf8AndControlCharactersGiveOneLineMessages) {
    const std::string what = errorOf("{\"characters\": [{\"name\": \"\xff\xfe\n\"}]}");
    EXPECT_NE(what.find("line 1"), std::string::npos) << what;
    for (const char c : what) {
        EXPECT_TRUE(c >= 0x20 && c < 0x7f) << "byte " << int(static_cast<unsigned char>(c)) << " in " << what;
    }
    EXPECT_EQ(errorOf(R"({"x\u000ay": 1})").rfind(R"(/x\u000ay: unknown key "x\u000ay")", 0), 0u);
}

TEST(SceneLoader, TruncatedFilesNeverCrash) {
    const std::string full = kFullScene;
    size_t accepted = 0;
    for (const size_t length : fuzz::truncationLengths(full.size(), 64, 400)) {
        SCOPED_TRACE("prefix of " + std::to_string(length) + " bytes");
        const std::string prefix = fuzz::truncated(full, length);
        expectWellFormedOutcome(prefix);
        accepted += parseScene(prefix, "t.json").ok() ? 1 : 0;
    }
    EXPECT_EQ(accepted, 0u);  // no proper prefix of an object is a JSON document
    expectWellFormedOutcome(full);
}

TEST(SceneLoader, RandomMutationsNeverCrash) {
    const std::string full = kFullScene;
    fuzz::Mutator mutator(20240611u, "{}[]\",:0123456789.-+eE truefalsnul\\/~\n");
    constexpr int kMutants = 300;
    size_t accepted = 0;
    for (int mutant = 0; mutant < kMutants; ++mutant) {
        const std::string text = mutator.mutate(full);
        SCOPED_TRACE("mutant " + std::to_string(mutant));
        expectWellFormedOutcome(text);
        accepted += parseScene(text, "m.json").ok() ? 1 : 0;
    }
    // Some mutations (inside strings, digits) stay valid: both paths are exercised.
    EXPECT_GT(accepted, 0u);
    EXPECT_LT(accepted, size_t(kMutants));
}

// Every value of the full scene, in turn, replaced by one of each JSON type.
TEST(SceneLoader, EveryValueWithEveryWrongTypeIsAWellFormedOutcome) {
    const nlohmann::json document = nlohmann::json::parse(kFullScene);
    const nlohmann::json flat = document.flatten();
    const std::vector<nlohmann::json> replacements = {
        "text", -1, 1e30, 2147483648.0, nullptr, true, nlohmann::json::array(), nlohmann::json::object(), {1, 2, 3}};
    size_t accepted = 0;
    for (const auto& [pointer, original] : flat.items()) {
        for (const nlohmann::json& replacement : replacements) {
            nlohmann::json edited = document;
            edited[nlohmann::json::json_pointer(pointer)] = replacement;
            SCOPED_TRACE(pointer + " = " + replacement.dump());
            const Result<Scene> scene = readSceneDocument(edited, "typed.json");
            if (scene.ok()) {
                ++accepted;
                continue;
            }
            EXPECT_EQ(scene.error().where, "typed.json");
            EXPECT_EQ(scene.error().what.find('\n'), std::string::npos) << scene.error().what;
        }
    }
    EXPECT_GT(accepted, 0u);  // e.g. a name that is any string, a scale that is 1e30
}

TEST(SceneLoader, MillionEntryArraysAreRefusedByTheirCaps) {
    auto repeated = [](const std::string& element, size_t count) {
        std::string text = "[";
        text.reserve(count * (element.size() + 1) + 2);
        for (size_t i = 0; i < count; ++i) {
            if (i) text += ',';
            text += element;
        }
        return text + "]";
    };
    constexpr size_t kMillion = 1000000;
    EXPECT_EQ(errorOf("{\"lights\": " + repeated("{}", kMillion) + "}"),
              "/lights: too many lights (1000000; at most 1024)");
    EXPECT_EQ(errorOf("{\"characters\": " + repeated("{}", kMillion) + "}"),
              "/characters: too many characters (1000000; at most 255)");
    EXPECT_EQ(errorOf("{\"camera\": {\"up\": " + repeated("0", kMillion) + "}}"),
              "/camera/up: expected an array of 3 numbers, got 1000000 elements");

    // The same from a file: the error names it.
    TempDir dir;
    const fs::path file = dir.path() / "million.json";
    std::ofstream(file) << "{\"lights\": " << repeated("{}", kMillion) << "}";
    const Result<Scene> scene = loadScene(file.string());
    ASSERT_FALSE(scene.ok());
    EXPECT_EQ(scene.error().where, file.string());
    EXPECT_NE(scene.error().what.find("too many lights"), std::string::npos) << scene.error().what;
}

TEST(SceneLoader, TruncatedFilesOnDiskNameTheFile) {
    TempDir dir;
    const std::string full = kFullScene;
    const fs::path file = dir.path() / "cut.json";
    for (const size_t length : fuzz::truncationLengths(full.size(), 8, 24)) {
        std::ofstream(file, std::ios::binary | std::ios::trunc) << fuzz::truncated(full, length);
        const Result<Scene> scene = loadScene(file.string());
        ASSERT_FALSE(scene.ok()) << length;
        EXPECT_EQ(scene.error().where, file.string());
    }
}

TEST(SceneTransform, ScalesThenRotatesXThenYThenZThenTranslates) {
    Transform t;
    t.translationM = glm::vec3(10.0f, 20.0f, 30.0f);
    t.rotationDeg = glm::vec3(90.0f, 90.0f, 90.0f);
    t.scale = 3.0f;
    // (0,1,0) * 3 * 0.5 = (0,1.5,0); Rx90 -> (0,0,1.5); Ry90 -> (1.5,0,0);
    // Rz90 -> (0,1.5,0); + translation. Z-first order would give (10,18.5,30).
    const glm::vec4 p = t.worldFromObject(0.5f) * glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    EXPECT_VEC3_NEAR(glm::vec3(p), glm::vec3(10.0f, 21.5f, 30.0f), 1e-5);
    EXPECT_FLOAT_EQ(p.w, 1.0f);
}

TEST(SceneTransform, EachAxisRotatesRightHanded) {
    Transform t;
    t.rotationDeg = glm::vec3(90.0f, 0.0f, 0.0f);
    EXPECT_VEC3_NEAR(glm::vec3(t.worldFromObject(1.0f) * glm::vec4(0, 1, 0, 1)), glm::vec3(0, 0, 1), 1e-6);
    t.rotationDeg = glm::vec3(0.0f, 90.0f, 0.0f);
    EXPECT_VEC3_NEAR(glm::vec3(t.worldFromObject(1.0f) * glm::vec4(0, 0, 1, 1)), glm::vec3(1, 0, 0), 1e-6);
    t.rotationDeg = glm::vec3(0.0f, 0.0f, 90.0f);
    EXPECT_VEC3_NEAR(glm::vec3(t.worldFromObject(1.0f) * glm::vec4(1, 0, 0, 1)), glm::vec3(0, 1, 0), 1e-6);
}

TEST(SceneTransform, TranslationIsNotScaledAndDirectionsIgnoreIt) {
    Transform t;
    t.translationM = glm::vec3(1.0f, 2.0f, 3.0f);
    t.scale = 2.0f;
    const glm::mat4 m = t.worldFromObject(0.01f);  // centimetre mesh
    EXPECT_VEC3_NEAR(glm::vec3(m * glm::vec4(100, 0, 0, 1)), glm::vec3(3, 2, 3), 1e-5);
    EXPECT_VEC3_NEAR(glm::vec3(m * glm::vec4(0, 0, 50, 0)), glm::vec3(0, 0, 1), 1e-6);
}

TEST(SceneLoader, EnvironmentParsesAndRoundTrips) {
    const Result<Scene> scene = parseScene(R"({"environment": {"source": "maps/sky.hdr", "intensity": 2.5,
        "rotation": {"axis": [0, 0, 2], "angle_deg": 30, "speed_deg_per_s": -5},
        "background": false, "occlusion": "ssao", "specular": "sh", "sh_bands": 2,
        "extract_light": "off", "extract_threshold": 30}})",
                                           "/scenes/x.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    const Environment& e = scene->environment;
    EXPECT_EQ(e.source, "/scenes/maps/sky.hdr");  // resolved from the scene file's folder
    EXPECT_EQ(e.intensity, 2.5f);
    EXPECT_EQ(e.rotation.axis, glm::vec3(0, 0, 1));  // normalised
    EXPECT_EQ(e.rotation.angleDeg, 30.0f);
    EXPECT_EQ(e.rotation.speedDegPerS, -5.0f);
    EXPECT_FALSE(e.background);
    EXPECT_EQ(e.occlusion, EnvironmentOcclusion::Ssao);
    EXPECT_EQ(e.specular, EnvironmentSpecular::Sh);
    EXPECT_EQ(e.shBands, 2);
    EXPECT_EQ(e.extractLight, EnvironmentLightExtraction::Off);
    EXPECT_EQ(e.extractThreshold, 30.0f);
    // The angle grows with time: 30 + (-5) x 2 = 20 degrees about +Z turns +X to (cos 20, sin 20, 0).
    const glm::vec3 turned = e.worldFromMap(2.0f) * glm::vec3(1, 0, 0);
    EXPECT_NEAR(turned.x, std::cos(glm::radians(20.0f)), 1e-6f);
    EXPECT_NEAR(turned.y, std::sin(glm::radians(20.0f)), 1e-6f);

    const Result<Scene> reread = parseScene(sceneToJson(*scene), scene->path);
    ASSERT_TRUE(reread.ok()) << reread.error().message();
    const Environment& r = reread->environment;
    EXPECT_EQ(r.source, e.source);
    EXPECT_EQ(r.intensity, e.intensity);
    EXPECT_EQ(r.rotation.axis, e.rotation.axis);
    EXPECT_EQ(r.rotation.angleDeg, e.rotation.angleDeg);
    EXPECT_EQ(r.background, e.background);
    EXPECT_EQ(r.occlusion, e.occlusion);
    EXPECT_EQ(r.specular, e.specular);
    EXPECT_EQ(r.shBands, e.shBands);
    EXPECT_EQ(r.extractLight, e.extractLight);
    EXPECT_EQ(r.extractThreshold, e.extractThreshold);

    const Result<Scene> builtIn = parseScene(R"({"environment": {"source": "studio"}})", "/scenes/x.json");
    ASSERT_TRUE(builtIn.ok());
    EXPECT_EQ(builtIn->environment.source, "studio");  // a built-in name is not a path
    EXPECT_EQ(builtIn->environment.extractLight, EnvironmentLightExtraction::Auto);  // on unless turned off
    EXPECT_FALSE(parseScene("{}", "x.json")->environment.enabled());
}

// A user profile given as Burley's normalized diffusion becomes its six-Gaussian
// fit. Checked against Burley's closed-form plane CDF (Christensen & Burley
// 2015; sss/BurleyProfile.h): 0.02, the fit's own bound (Burley* tests). Scaling
// the mean free path by 1.05 in the loader fails 3 of the radii.
TEST(SceneLoader, BurleyProfileIsFittedWithGaussians) {
    const Result<Scene> scene = parseScene(R"({"profiles": {"soft": {"burley": {"albedo": [0.8, 0.6, 0.5],
        "mean_free_path_mm": [1.0, 0.4, 0.25]}}}})",
                                           "x.json");
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    ASSERT_EQ(scene->profiles.size(), 1u);
    const DiffusionProfile& profile = scene->profiles[0];
    EXPECT_EQ(profile.name(), "soft");
    EXPECT_EQ(profile.size(), 6u);
    const BurleyParameters parameters{{0.8f, 0.6f, 0.5f}, {1.0f, 0.4f, 0.25f}};
    for (double r : {0.05, 0.2, 0.5, 1.0, 2.0, 5.0}) {
        const glm::dvec3 expected = burleyRadialCdf(parameters, r);
        const glm::dvec3 fitted = gaussianRadialCdf(profile, r);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(fitted[c], expected[c], 0.02) << "r " << r << " channel " << c;
    }
    EXPECT_EQ(errorOf(R"({"profiles": {"soft": {"burley": {"albedo": [0.8, 0.6, 0.5]}}}})"),
              "/profiles/soft/burley: needs \"albedo\" and \"mean_free_path_mm\"");
    EXPECT_EQ(errorOf(R"({"profiles": {"soft": {"burley": {"albedo": [0.8, 0.6, 0.5], "mean_free_path_mm": [1, 0, 1]}}}})")
                  .rfind("/profiles/soft/burley/mean_free_path_mm/1:", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"profiles": {"soft": {"burley": {"albedo": [1, 1, 1], "mean_free_path_mm": [1, 1, 1]},
        "gaussians": [{"variance_mm2": 1, "weights": [1, 1, 1]}]}}})"),
              "/profiles/soft: give \"gaussians\" or \"burley\", not both");
}

// The stored float is range-checked. A bound that is not a float (1e20 rounds
// up to 1.00000002e20) is accepted as written, stored as the float next to it
// inside the range; past the bound the value is refused.
TEST(SceneLoader, BoundThatIsNotAFloatIsAcceptedAsWritten) {
    auto scene = parseScene(R"({"background": {"colour": [1e20, 0, 0]}})", "x.json");
    ASSERT_TRUE(scene) << scene.error().message();
    EXPECT_LE(double(scene->background.colour.r), 1e20);
    EXPECT_EQ(errorOf(R"({"background": {"colour": [2e20, 0, 0]}})"),
              "/background/colour/0: must be in [0, 1e+20], got 2e+20");
}

TEST(SceneLoader, BadEnvironmentsNameTheKey) {
    EXPECT_EQ(errorOf(R"({"environment": {"intensity": 1}})"),
              "/environment/source: is required: a built-in environment (sky, studio or uniform) or a lat-long map file");
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "rotation": {"axis": [0, 0, 0]}}})"),
              "/environment/rotation/axis: must not be the zero vector");
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "sh_bands": 4}})").rfind("/environment/sh_bands:", 0), 0u);
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "occlusion": "ambient"}})")
                  .rfind("/environment/occlusion: unknown environment occlusion", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "intensity": -1}})").rfind("/environment/intensity:", 0), 0u);
    EXPECT_EQ(errorOf(R"({"environment": {"source": ""}})").rfind("/environment/source:", 0), 0u);
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "extract_light": "on"}})")
                  .rfind("/environment/extract_light: unknown environment light extraction", 0),
              0u);
    EXPECT_EQ(errorOf(R"({"environment": {"source": "sky", "extract_threshold": 1}})"),
              "/environment/extract_threshold: must be in [2, 1e+09], got 1");
}

}  // namespace
}  // namespace dermis

// A documented bound is accepted as written (1e20 is not a float: it is
// stored as the float next to it inside the range), and the characters a
// file may list are those the renderer tells apart.
TEST(SceneLoader, DocumentedBoundsAreAcceptedAndTheCharacterCapIsTheRenderers) {
    auto bound = dermis::parseScene(R"({"environment": {"source": "sky", "intensity": 1e20}})", "b.json");
    ASSERT_TRUE(bound) << bound.error().message();
    EXPECT_LE(double(bound->environment.intensity), 1e20);
    EXPECT_GT(double(bound->environment.intensity), 0.99e20);
    std::string many = R"({"characters": [)";
    for (int i = 0; i < 256; ++i) many += std::string(i ? "," : "") + R"({"name": "c", "mesh": {"procedural": "plane"}})";
    many += "]}";
    auto tooMany = dermis::parseScene(many, "m.json");
    ASSERT_FALSE(tooMany);
    EXPECT_NE(tooMany.error().message().find("255"), std::string::npos) << tooMany.error().message();
}
