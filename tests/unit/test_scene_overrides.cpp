// Command-line overrides of scene keys ("--set sss.taps=13"): paths, the
// settings shorthand, value parsing, precedence over the file, and errors that
// name the override.

#include "scene/JsonReader.h"
#include "scene/SceneLoader.h"
#include "scene/SceneOverrides.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace dermis {
namespace {

namespace fs = std::filesystem;

constexpr const char* kScene = R"({
  "camera": {"position_m": [0, 0, 1], "near_m": 0.05, "far_m": 50},
  "lights": [{"type": "directional"}, {"type": "spot", "position_m": [0, 1, 1], "shadow": true}],
  "characters": [{"name": "head", "mesh": {"procedural": "head"}, "material": {"roughness": 0.3}}],
  "settings": {"exposure": 1.5, "sss": {"taps": 9, "blur": "bilateral"}}
})";

Scene load(const std::vector<std::string>& overrides, const std::string& text = kScene) {
    Result<Scene> scene = parseSceneWithOverrides(text, "x.json", overrides);
    EXPECT_TRUE(scene.ok()) << scene.error().message();
    return scene.ok() ? *scene : Scene{};
}

Error errorOf(const std::vector<std::string>& overrides, const std::string& text = kScene) {
    const Result<Scene> scene = parseSceneWithOverrides(text, "x.json", overrides);
    EXPECT_FALSE(scene.ok()) << "accepted";
    if (scene.ok()) {
        return Error{};
    }
    EXPECT_EQ(scene.error().message().find('\n'), std::string::npos) << scene.error().message();
    return scene.error();
}

#define EXPECT_ERROR(error, expectedWhere, expectedWhat) \
    do {                                                 \
        const Error e = (error);                         \
        EXPECT_EQ(e.where, expectedWhere);               \
        EXPECT_EQ(e.what, expectedWhat);                 \
    } while (false)

TEST(SceneOverrides, NoOverridesIsParseScene) {
    const Scene scene = load({});
    EXPECT_EQ(scene.settings.exposure, 1.5f);
    EXPECT_EQ(scene.path, "x.json");
}

TEST(SceneOverrides, ShorthandPathsAreUnderSettings) {
    EXPECT_EQ(load({"sss.taps=13"}).settings.sss.taps, 13);
    EXPECT_EQ(load({"settings.sss.taps=13"}).settings.sss.taps, 13);
    EXPECT_EQ(load({"exposure=2.5"}).settings.exposure, 2.5f);
    EXPECT_EQ(load({"shadow.map_size=4096"}).settings.shadow.mapSize, 4096);
    EXPECT_EQ(load({"ssao.radius_m=0.05"}).settings.ssao.radiusM, 0.05f);
    EXPECT_EQ(load({"transmittance.strength=3"}).settings.transmittance.strength, 3.0f);
}

TEST(SceneOverrides, FullPathsReachEveryRootKey) {
    const Scene scene = load({"camera.position_m=[0,0.1,0.5]", "characters.0.material.roughness=0.4",
                              "lights.1.shadow=false", "background.colour=[0.5, 0.25, 0]", "camera.far_m=20"});
    EXPECT_EQ(scene.camera.positionM, glm::vec3(0.0f, 0.1f, 0.5f));
    EXPECT_EQ(scene.camera.farM, 20.0f);
    EXPECT_EQ(scene.characters[0].material.roughness, 0.4f);
    EXPECT_FALSE(scene.lights[1].castsShadow);
    EXPECT_TRUE(scene.lights[0].castsShadow);
    EXPECT_EQ(scene.background.colour, glm::vec3(0.5f, 0.25f, 0.0f));
}

TEST(SceneOverrides, ArrayElementsAndWholeValuesCanBeReplaced) {
    const Scene scene = load({"lights.0={\"type\": \"point\", \"intensity\": 4}", "characters.0.ssao={\"samples\": 32}"});
    EXPECT_EQ(scene.lights[0].type, LightType::Point);
    EXPECT_EQ(scene.lights[0].intensity, 4.0f);
    EXPECT_EQ(scene.characters[0].ssao.samples, 32);
    EXPECT_EQ(load({"lights=[]"}).lights.size(), 0u);
    // Replacing an object drops the file's keys in it: they take the defaults.
    const Scene sss = load({"sss={\"mix\": 0.25}"});
    EXPECT_EQ(sss.settings.sss.mix, 0.25f);
    EXPECT_EQ(sss.settings.sss.taps, SssSettings{}.taps);
}

TEST(SceneOverrides, BooleansAndNumbersAreJson) {
    const Scene off = load({"ssao.enabled=false", "energy_conservation=false", "sss.enabled=false",
                            "transmittance.enabled=false", "ssao.blur=false"});
    EXPECT_FALSE(off.settings.ssao.enabled);
    EXPECT_FALSE(off.settings.energyConservation);
    EXPECT_FALSE(off.settings.sss.enabled);
    EXPECT_FALSE(off.settings.transmittance.enabled);
    EXPECT_FALSE(off.settings.ssao.blur);
    EXPECT_TRUE(load({"ssao.enabled=true"}).settings.ssao.enabled);
    EXPECT_EQ(load({"exposure=1e-2"}).settings.exposure, 0.01f);
    EXPECT_EQ(load({"sss.taps= 15 "}).settings.sss.taps, 15);  // JSON allows surrounding whitespace
}

TEST(SceneOverrides, ValuesThatAreNotJsonAreBareStrings) {
    EXPECT_EQ(load({"sss.blur=control"}).settings.sss.blur, SssBlur::Control);
    EXPECT_EQ(load({"sss.blur=\"control\""}).settings.sss.blur, SssBlur::Control);
    EXPECT_EQ(load({"shadow.filter=poisson"}).settings.shadow.filter, ShadowFilter::Poisson);
    EXPECT_EQ(load({"characters.0.name=lee"}).characters[0].name, "lee");
    EXPECT_EQ(load({"characters.0.name=\"42\""}).characters[0].name, "42");
    EXPECT_EQ(load({"characters.0.name=a=b"}).characters[0].name, "a=b");  // PATH ends at the first '='
    EXPECT_EQ(load({"characters.0.name="}).characters[0].name, "");
    EXPECT_EQ(load({"characters.0.material.profile=marble"}).characters[0].material.profile, "marble");
}

TEST(SceneOverrides, OverrideBeatsTheFileAndLaterBeatsEarlier) {
    EXPECT_EQ(load({}).settings.exposure, 1.5f);
    EXPECT_EQ(load({"exposure=0.5"}).settings.exposure, 0.5f);
    EXPECT_EQ(load({"sss.taps=5", "settings.sss.taps=7"}).settings.sss.taps, 7);
    // Overrides are applied before the file is checked: one can repair a bad value.
    EXPECT_EQ(load({"sss.taps=5"}, R"({"settings": {"sss": {"taps": 4}}})").settings.sss.taps, 5);
    // Neighbouring keys from the file survive.
    const Scene scene = load({"sss.taps=5"});
    EXPECT_EQ(scene.settings.sss.blur, SssBlur::Bilateral);
    EXPECT_EQ(scene.settings.exposure, 1.5f);
}

TEST(SceneOverrides, KeysAbsentFromTheFileAreCreated) {
    const Scene scene = load({"ssao.samples=64", "transmittance.shrink_mm=0.5", "characters.0.ssao.radius_m=0.01",
                              "characters.0.transform.scale=2"});
    EXPECT_EQ(scene.settings.ssao.samples, 64);
    EXPECT_EQ(scene.settings.transmittance.shrinkMm, 0.5f);
    EXPECT_EQ(scene.characters[0].ssao.radiusM, 0.01f);
    EXPECT_EQ(scene.characters[0].transform.scale, 2.0f);
    const Scene empty = load({"sss.taps=13", "camera.near_m=0.01"}, "{}");
    EXPECT_EQ(empty.settings.sss.taps, 13);
    EXPECT_EQ(empty.camera.nearM, 0.01f);
}

TEST(SceneOverrides, ValuesTheReaderRejectsNameTheOverride) {
    EXPECT_ERROR(errorOf({"sss.taps=4"}), "--set sss.taps=4",
                 "/settings/sss/taps: must be an odd number of taps in [3, 33], got 4");
    EXPECT_ERROR(errorOf({"settings.ssao.samples=4"}), "--set settings.ssao.samples=4",
                 "/settings/ssao/samples: must be in [8, 128], got 4");
    EXPECT_ERROR(errorOf({"sss.blur=gauss"}), "--set sss.blur=gauss",
                 "/settings/sss/blur: unknown SSS blur \"gauss\" (expected variant, bilateral, control or fetch-only)");
    EXPECT_ERROR(errorOf({"exposure=bright"}), "--set exposure=bright",
                 "/settings/exposure: expected a number, got a string");
    EXPECT_ERROR(errorOf({"lights.1.shadow=1"}), "--set lights.1.shadow=1",
                 "/lights/1/shadow: expected true or false, got a number");
    EXPECT_ERROR(errorOf({"characters.0.name=42"}), "--set characters.0.name=42",
                 "/characters/0/name: expected a string, got a number");
    EXPECT_ERROR(errorOf({"camera.position_m=[0,0.1"}), "--set camera.position_m=[0,0.1",
                 "the value is not valid JSON: parse error at line 1, column 7: syntax error while parsing array - "
                 "unexpected end of input; expected ']'");
    EXPECT_ERROR(errorOf({"characters.0.ssao.samples=3"}), "--set characters.0.ssao.samples=3",
                 "/characters/0/ssao/samples: must be 0 (use settings.ssao.samples) or in [8, 128], got 3");
    // An object value is checked inside too.
    EXPECT_ERROR(errorOf({"sss={\"taps\": 2}"}), "--set sss={\"taps\": 2}",
                 "/settings/sss/taps: must be an odd number of taps in [3, 33], got 2");
    EXPECT_ERROR(errorOf({"characters.0={}"}), "--set characters.0={}", "/characters/0: missing required key \"mesh\"");
    // Names the engine defines are checked while loading, so the error names the override and the key.
    EXPECT_ERROR(errorOf({"characters.0.material.profile=marble2"}), "--set characters.0.material.profile=marble2",
                 "/characters/0/material/profile: unknown diffusion profile \"marble2\": did you mean \"marble\"? (known: skin, marble or none)");
    // A number no double holds is out of range, not a string.
    EXPECT_ERROR(errorOf({"exposure=1e999"}), "--set exposure=1e999",
                 "/settings/exposure: number 1e999 is out of range (finite numbers reach about +-1.8e308)");
    EXPECT_ERROR(errorOf({"exposure=-1e400"}), "--set exposure=-1e400",
                 "/settings/exposure: number -1e400 is out of range (finite numbers reach about +-1.8e308)");
}

TEST(SceneOverrides, UnknownKeysNameTheOverride) {
    EXPECT_ERROR(errorOf({"sss.tap=5"}), "--set sss.tap=5",
                 "/settings/sss/tap: unknown key \"tap\": did you mean \"taps\"? (known: enabled, variant, blur, technique, taps, gaussians, "
                 "separable_samples, disk_samples, bilateral_depth_mm, control_depth_scale_per_mm, width_scale, min_width_px, mix and lean_moment_width_mm)");
    EXPECT_EQ(errorOf({"foo=1"}).what.rfind("/settings/foo: unknown key \"foo\"", 0), 0u);
    const Error nested = errorOf({"sss.extra.deep=1"});
    EXPECT_EQ(nested.where, "--set sss.extra.deep=1");
    EXPECT_EQ(nested.what.rfind("/settings/sss/extra: unknown key \"extra\"", 0), 0u) << nested.what;
    EXPECT_EQ(errorOf({"characters.0.colour=[1,1,1]"}).where, "--set characters.0.colour=[1,1,1]");
}

TEST(SceneOverrides, ChecksAcrossKeysNameTheOverrideThatBrokeThem) {
    EXPECT_ERROR(errorOf({"camera.far_m=0.01"}), "--set camera.far_m=0.01",
                 "/camera/near_m: must be less than far_m (0.01), got 0.05");
    EXPECT_ERROR(errorOf({"exposure=2", "camera.position_m=[0,0,0]"}), "--set camera.position_m=[0,0,0]",
                 "/camera/target_m: must be at least 1e-06 m from position_m (the camera needs a view direction)");
    EXPECT_ERROR(errorOf({"characters.0.mesh.gltf=a.glb"}), "--set characters.0.mesh.gltf=a.glb",
                 "/characters/0/mesh: give exactly one of \"procedural\" and \"gltf\", not both");
}

TEST(SceneOverrides, ErrorsInTheFileStayTheFiles) {
    const std::string badFile = R"({"settings": {"sss": {"taps": 4}}})";
    EXPECT_ERROR(errorOf({"ssao.samples=16"}, badFile), "x.json",
                 "/settings/sss/taps: must be an odd number of taps in [3, 33], got 4");
    EXPECT_ERROR(errorOf({"exposure=2"}, R"({"characters": [{"name": "x"}]})"), "x.json",
                 "/characters/0: missing required key \"mesh\"");
    EXPECT_ERROR(errorOf({"characters.0.name=y"}, R"({"characters": [{"name": "x"}]})"), "x.json",
                 "/characters/0: missing required key \"mesh\"");
    EXPECT_EQ(errorOf({"exposure=2"}, "{\"settings\": }").where, "x.json");
    EXPECT_ERROR(errorOf({"exposure=2"}, "[]"), "x.json", "expected an object, got an array");
}

TEST(SceneOverrides, TheFirstErrorInReadingOrderIsReported) {
    // settings.sss is read before settings.ssao, whatever the order on the command line.
    EXPECT_EQ(errorOf({"sss.taps=4", "ssao.samples=3"}).where, "--set sss.taps=4");
    EXPECT_EQ(errorOf({"ssao.samples=3", "sss.taps=4"}).where, "--set sss.taps=4");
    EXPECT_EQ(errorOf({"sss.taps=4", "sss.taps=4"}).where, "--set sss.taps=4");
    // The last of two overrides of one key is the one in effect.
    EXPECT_ERROR(errorOf({"sss.taps=4", "sss.taps=6"}), "--set sss.taps=6",
                 "/settings/sss/taps: must be an odd number of taps in [3, 33], got 6");
    EXPECT_EQ(errorOf({"sss.taps=4", "sss.taps=5", "exposure=0"}).where, "--set exposure=0");
}

TEST(SceneOverrides, MalformedOverridesAreNamed) {
    EXPECT_ERROR(errorOf({"x"}), "--set x", "expected PATH=VALUE");
    EXPECT_ERROR(errorOf({"=5"}), "--set =5", "expected PATH=VALUE");
    EXPECT_ERROR(errorOf({""}), "--set ", "expected PATH=VALUE");
    EXPECT_ERROR(errorOf({"sss..taps=5"}), "--set sss..taps=5",
                 "expected PATH=VALUE, with no empty key in PATH \"sss..taps\"");
    EXPECT_EQ(errorOf({".taps=5"}).what.rfind("expected PATH=VALUE", 0), 0u);
    EXPECT_EQ(errorOf({"sss.=5"}).what.rfind("expected PATH=VALUE", 0), 0u);
    // A malformed override is reported before the file is read.
    EXPECT_EQ(errorOf({"exposure=2", "bad"}, "not json").where, "--set bad");
    // Control characters do not break the message onto two lines.
    EXPECT_EQ(errorOf({"a\nb"}).where, "--set a?b");
    // An array or object that does not parse is an error, not a string: one
    // nested deeper than the reader's limit, and one with a syntax error.
    const std::string deep = "lights=" + std::string(kMaxNestingDepth + 1, '[') + std::string(kMaxNestingDepth + 1, ']');
    const Error tooDeep = errorOf({deep});
    EXPECT_EQ(tooDeep.where.rfind("--set lights=[[[", 0), 0u) << tooDeep.message();
    EXPECT_NE(tooDeep.what.find("nested deeper than " + std::to_string(kMaxNestingDepth)), std::string::npos)
        << tooDeep.message();
    EXPECT_EQ(errorOf({"ambient=[0.1, 0.2"}).what.rfind("the value is not valid JSON: ", 0), 0u);
    EXPECT_EQ(errorOf({"camera= {\"fov\": }"}).what.rfind("the value is not valid JSON: ", 0), 0u);
    // Just inside the limit it parses (and is then refused as the wrong type, by key).
    const std::string deepest = "ambient=" + std::string(kMaxNestingDepth, '[') + std::string(kMaxNestingDepth, ']');
    EXPECT_EQ(errorOf({deepest}).what.find("not valid JSON"), std::string::npos);
}

TEST(SceneOverrides, ArrayElementsMustExist) {
    EXPECT_ERROR(errorOf({"lights.2.shadow=false"}), "--set lights.2.shadow=false",
                 "/lights/2: no such array element (/lights has 2 elements)");
    EXPECT_ERROR(errorOf({"characters.1={\"mesh\": {\"procedural\": \"head\"}}"}),
                 "--set characters.1={\"mesh\": {\"procedural\": \"head\"}}",
                 "/characters/1: no such array element (/characters has 1 element)");
    EXPECT_ERROR(errorOf({"lights.99999999999999999999999.shadow=false"}),
                 "--set lights.99999999999999999999999.shadow=false",
                 "/lights/99999999999999999999999: no such array element (/lights has 2 elements)");
    EXPECT_ERROR(errorOf({"characters.0.name=x"}, "{}"), "--set characters.0.name=x",
                 "/characters/0: no such array element (/characters is absent)");
    EXPECT_ERROR(errorOf({"lights.first.shadow=false"}), "--set lights.first.shadow=false",
                 "/lights: expected an array index, got \"first\"");
    EXPECT_ERROR(errorOf({"lights.-1.shadow=false"}), "--set lights.-1.shadow=false",
                 "/lights: expected an array index, got \"-1\"");
}

TEST(SceneOverrides, CannotSetInsideAValueThatIsNotAnObject) {
    EXPECT_ERROR(errorOf({"exposure.value=1"}), "--set exposure.value=1",
                 "/settings/exposure: cannot set \"value\" inside a number");
    EXPECT_ERROR(errorOf({"camera.position_m.x=1"}), "--set camera.position_m.x=1",
                 "/camera/position_m: expected an array index, got \"x\"");
    EXPECT_ERROR(errorOf({"sss.taps=3"}, R"({"settings": {"sss": null}})"), "--set sss.taps=3",
                 "/settings/sss: cannot set \"taps\" inside null");
}

TEST(SceneOverrides, ParsedOverrideExposesItsPathAndValue) {
    const Result<SceneOverride> change = parseSceneOverride("sss.taps=13");
    ASSERT_TRUE(change.ok()) << change.error().message();
    EXPECT_EQ(change->path, (std::vector<std::string>{"settings", "sss", "taps"}));
    EXPECT_EQ(change->pointer(), "/settings/sss/taps");
    EXPECT_EQ(change->where(), "--set sss.taps=13");
    EXPECT_EQ(change->value, nlohmann::json(13));
    for (const char* root : {"camera", "lights", "characters", "background", "settings"}) {
        const Result<SceneOverride> rooted = parseSceneOverride(std::string(root) + "=1");
        ASSERT_TRUE(rooted.ok());
        EXPECT_EQ(rooted->path, std::vector<std::string>{root});
    }
    const Result<SceneOverride> bare = parseSceneOverride("sss.blur=control");
    ASSERT_TRUE(bare.ok());
    EXPECT_EQ(bare->value, nlohmann::json("control"));
    const Result<SceneOverride> array = parseSceneOverride("camera.up=[0, 1, 0]");
    ASSERT_TRUE(array.ok());
    EXPECT_EQ(array->value, nlohmann::json::array({0, 1, 0}));
}

TEST(SceneOverrides, LoadSceneAppliesOverridesToTheFile) {
    const fs::path file =
        fs::temp_directory_path() / ("dermis_overrides_test_" + std::to_string(std::random_device{}()) + ".json");
    std::ofstream(file) << kScene;
    const Result<Scene> scene = loadScene(file.string(), {"sss.taps=13", "ssao.enabled=false"});
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_EQ(scene->path, file.string());
    EXPECT_EQ(scene->settings.sss.taps, 13);
    EXPECT_FALSE(scene->settings.ssao.enabled);
    EXPECT_EQ(scene->settings.exposure, 1.5f);
    const Result<Scene> bad = loadScene(file.string(), {"sss.taps=4"});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message(),
              "--set sss.taps=4: /settings/sss/taps: must be an odd number of taps in [3, 33], got 4");
    fs::remove(file);

    const Result<Scene> missing = loadScene("/nonexistent/dermis/scene.json", {"sss.taps=13"});
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().what, "cannot open scene file: No such file or directory");
}

TEST(SceneOverrides, OverriddenScenesRoundTrip) {
    const Scene scene = load({"sss.blur=control", "sss.mix=0.3", "shadow.filter=poisson", "lights.0.intensity=2.5"});
    const Result<Scene> again = parseScene(sceneToJson(scene), "x.json");
    ASSERT_TRUE(again.ok()) << again.error().message();
    EXPECT_EQ(again->settings.sss.blur, SssBlur::Control);
    EXPECT_EQ(again->settings.sss.mix, 0.3f);
    EXPECT_EQ(again->settings.shadow.filter, ShadowFilter::Poisson);
    EXPECT_EQ(again->lights[0].intensity, 2.5f);
}

// Random combinations of paths and values: never a crash, and every error is
// one line naming either the file or one of the overrides.
TEST(SceneOverrides, RandomOverridesGiveWellFormedOutcomes) {
    const std::vector<std::string> paths = {
        "sss.taps", "sss", "ssao.samples", "exposure", "lights.0", "lights.1.shadow", "lights.5.type",
        "characters.0.ssao.samples", "characters.0.mesh", "camera.up", "camera", "background.colour",
        "settings", "shadow.map_size.x", "", "a..b", "characters.x", "0", "transmittance.strength"};
    const std::vector<std::string> values = {"13", "4", "false", "null", "[0,1,0]", "[", "{}", "control", "\"x\"",
                                             "-1", "1e999", "{\"taps\": 7}", "", "=", "0.5", "[]", "\"\\u0000\""};
    std::mt19937 random(7u);
    size_t accepted = 0;
    for (int round = 0; round < 300; ++round) {
        std::vector<std::string> overrides;
        const size_t count = 1 + random() % 3;
        for (size_t i = 0; i < count; ++i) {
            overrides.push_back(paths[random() % paths.size()] + "=" + values[random() % values.size()]);
        }
        const Result<Scene> scene = parseSceneWithOverrides(kScene, "x.json", overrides);
        if (scene.ok()) {
            ++accepted;
            continue;
        }
        const Error& e = scene.error();
        EXPECT_EQ(e.message().find('\n'), std::string::npos) << e.message();
        EXPECT_FALSE(e.what.empty());
        bool named = e.where == "x.json";
        for (const std::string& o : overrides) {
            named = named || e.where == "--set " + o;
        }
        EXPECT_TRUE(named) << e.message();
        EXPECT_NE(e.where, "x.json") << "the file is valid: " << e.message();
    }
    EXPECT_GT(accepted, 0u);
    EXPECT_LT(accepted, 300u);
}

}  // namespace
}  // namespace dermis
