#include "stress/StressCases.h"

#include "core/Limits.h"
#include "stress/StressHostile.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <random>
#include <vector>

namespace dermis::stress {
namespace {

class Dice {
public:
    explicit Dice(uint64_t seed) : mRng(seed * 0x9E3779B97F4A7C15ull + 1) {}
    template <class T>
    const T& pick(const std::vector<T>& options) {
        return options[std::uniform_int_distribution<size_t>(0, options.size() - 1)(mRng)];
    }
    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(mRng) < p; }
    float uniform(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(mRng); }
    std::mt19937_64& rng() { return mRng; }
    glm::vec3 direction() {
        glm::vec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        return glm::length(d) < 1e-3f ? glm::vec3(0, -1, 0) : d;
    }

private:
    std::mt19937_64 mRng;
};

void note(std::string& description, const std::string& what) {
    if (description.find(what) != std::string::npos) return;
    if (!description.empty()) description += ", ";
    description += what;
}

Character makeCharacter(Dice& dice, const std::string& assets, int index, std::string& description) {
    Character c;
    c.name = "c" + std::to_string(index);
    const std::string mesh = dice.pick<std::string>(
        {"plane", "sphere", "wedge", "sphere", "head", "degenerate", "no_normals", "no_uvs", "duplicates"});
    if (mesh == "degenerate") {
        c.mesh.gltfPath = assets + "/degenerate.gltf";
        note(description, "degenerate and zero-area triangles, zero normals");
    } else if (mesh == "no_normals" || mesh == "no_uvs" || mesh == "duplicates") {
        c.mesh.gltfPath = assets + "/" + mesh + ".gltf";
        note(description, "glTF " + mesh);
    } else {
        c.mesh.procedural = mesh;
    }
    if (mesh == "head") c.material.procedural = true;
    c.transform.translationM = glm::vec3(dice.uniform(-0.2f, 0.2f), dice.uniform(-0.1f, 0.1f), dice.uniform(-0.2f, 0.2f));
    c.transform.rotationDeg = glm::vec3(dice.uniform(-180, 180), dice.uniform(-180, 180), dice.uniform(-180, 180));
    c.transform.scale = dice.pick<float>({1.0f, 1.0f, 0.01f, 5.0f});
    // 0.045: the scan's 4.5 cm per unit (docs/scenes.md).
    c.metresPerUnit = dice.pick<float>({1.0f, 1.0f, 0.045f, 1e-3f, 10.0f});
    c.material.profile = dice.pick<std::string>({"skin", "skin", "marble", std::string(kOpaqueProfile)});
    c.material.roughness = dice.pick<float>({1e-6f, 0.05f, 0.3f, 1.0f});
    c.material.rhoS = dice.pick<float>({0.0f, 0.18f, 1.0f});
    if (dice.chance(0.15)) {
        c.material.albedoMap = assets + "/nan_albedo.exr";
        c.material.normalMap = assets + "/nan_normal.exr";
        note(description, "NaN/Inf texels in the maps");
    }
    c.ssao.samples = dice.pick<int>({0, 8, 128});
    c.ssao.radiusM = dice.pick<float>({0.0f, 1e-5f, 0.02f, 50.0f});
    return c;
}

Light makeLight(Dice& dice, std::string& description) {
    Light light;
    light.type = dice.pick<LightType>(kLightTypes.values());
    light.direction = dice.direction();
    light.positionM = dice.direction() * dice.uniform(0.05f, 2.0f);
    const float colourScale = dice.pick<float>({1.0f, 1.0f, 4.0f});  // above 1: a colour past white
    light.colour = colourScale * glm::vec3(dice.uniform(0, 1), dice.uniform(0, 1), dice.uniform(0, 1));
    // The largest intensity: colour (up to 4) x intensity just under the
    // loader's kMaxLightRadiance.
    light.intensity = dice.pick<float>({0.0f, 1.0f, 3.0f, 1e5f, float(kMaxLightRadiance) / 4.5f});
    if (light.intensity > 65504.0f) note(description, "light past fp16");
    light.spotInnerDeg = dice.uniform(0, 60);
    light.spotOuterDeg = light.spotInnerDeg + dice.pick<float>({0.0f, 5.0f, 20.0f});
    light.castsShadow = dice.chance(0.7);
    // Up to just under the loader's limits (rightOpen ranges).
    light.angularDiameterDeg = dice.pick<float>({0.0f, 0.53f, 5.0f, float(kMaxLightAngularDiameterDeg) * 0.999f});
    light.radiusM = dice.pick<float>({0.0f, 0.01f, 0.2f, float(kMaxLightRadiusM) * 0.999f});
    return light;
}

std::string formatNumber(double x) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.9g", x);
    return text;
}

// Legal `--set` overrides: settings and scene values in range, in the syntax of SceneOverrides.h.
std::vector<std::string> makeOverrides(Dice& dice, const Scene& scene) {
    std::vector<std::string> overrides;
    const int count = dice.pick<int>({1, 2, 3});
    for (int i = 0; i < count; ++i) {
        switch (dice.pick<int>({0, 1, 2, 3, 4, 5})) {
        case 0: overrides.push_back("sss.taps=" + std::to_string(2 * dice.pick<int>({1, 4, 12}) + 1)); break;
        case 1: overrides.push_back("settings.exposure=" + formatNumber(dice.pick<double>({1e-3, 2.0, 9e3}))); break;
        case 2: overrides.push_back("mode=" + std::string(kSssModes.name(dice.pick<SssMode>(kSssModes.values())))); break;
        case 3:
            overrides.push_back("sss.variant=" +
                                std::string(kSssVariants.name(dice.pick<SssVariant>(kSssVariants.values()))));
            break;
        case 4: overrides.push_back("background.colour=[0.2, 3, 0]"); break;
        default:
            if (!scene.lights.empty()) overrides.push_back("lights.0.intensity=" + formatNumber(dice.uniform(0, 10)));
            else overrides.push_back("shadow.filter=pcf4x4");
            break;
        }
    }
    return overrides;
}

void makeHostile(Dice& dice, StressCase& c) {
    const std::vector<HostileValue>& values = hostileValues();
    const HostileValue& value = values[std::uniform_int_distribution<size_t>(0, values.size() - 1)(dice.rng())];
    c.path = CasePath::Hostile;
    c.refusal.key = value.key;
    c.refusal.range = value.range;
    c.refusal.throughOverride = value.override != nullptr && (value.spoil == nullptr || dice.chance(0.5));
    if (c.refusal.throughOverride) {
        c.overrides.push_back(value.override(c.scene));
    } else {
        value.spoil(c.scene);
    }
    c.description = "hostile: " + value.name + (c.refusal.throughOverride ? " (--set)" : " (file)");
}

}  // namespace

StressCase makeStressCase(uint64_t seed, const std::string& assets) {
    Dice dice(seed);
    StressCase c;
    c.seed = seed;
    c.assetDirectory = assets;
    Scene& scene = c.scene;
    // The file a Loader or Hostile case writes; Memory cases name it too, so
    // that asset paths written relative to it read back the same.
    scene.path = assets + "/case-" + std::to_string(seed) + ".json";

    const int characters = dice.pick<int>({1, 1, 2, 3});
    for (int i = 0; i < characters; ++i) scene.characters.push_back(makeCharacter(dice, assets, i, c.description));

    const int lights = dice.pick<int>({0, 1, 2, 3, 64});
    if (lights == 0) note(c.description, "no lights");
    if (lights == 64) note(c.description, "64 lights");
    for (int i = 0; i < lights; ++i) scene.lights.push_back(makeLight(dice, c.description));

    Camera& camera = scene.camera;
    // Just above the loader's 1e-4 m: the float nearest 1e-4 is below it.
    camera.nearM = dice.pick<float>({float(kMinNearM) * 1.0001f, 0.01f, 0.05f, 0.5f});
    // 0.9999e5, not 1e5: far = near x 1e5 in floats can round past the limit.
    camera.farM = camera.nearM * dice.pick<float>({1.01f, 100.0f, float(kMaxFarOverNear) * 0.9999f});
    if (camera.nearM < 1e-3f || camera.farM / camera.nearM > 1e4f) note(c.description, "extreme near/far planes");
    camera.verticalFovDeg = dice.pick<float>({1.0f, 35.0f, 120.0f, 179.0f});
    camera.targetM = scene.characters.front().transform.translationM;
    const std::string placement = dice.pick<std::string>({"front", "front", "inside", "grazing", "far"});
    if (placement == "inside") {
        camera.positionM = camera.targetM + glm::vec3(0.001f, 0.002f, 0.003f);
        note(c.description, "camera inside a character");
    } else if (placement == "grazing") {
        camera.positionM = camera.targetM + glm::vec3(0.4f, 0.0005f, 0.0f);
        note(c.description, "grazing view");
    } else if (placement == "far") {
        camera.positionM = camera.targetM + glm::vec3(0.0f, 0.0f, 200.0f);
    } else {
        camera.positionM = camera.targetM + dice.direction() * 0.4f + glm::vec3(0.0f, 0.0f, 0.01f);
    }
    if (glm::length(camera.positionM - camera.targetM) < 1e-6f) camera.positionM.z += 0.01f;
    camera.up = std::abs(glm::normalize(camera.targetM - camera.positionM).y) > 0.99f ? glm::vec3(0, 0, 1)
                                                                                       : glm::vec3(0, 1, 0);

    RenderSettings& s = scene.settings;
    s.mode = dice.chance(0.25) ? SssMode::TextureSpace : SssMode::ScreenSpace;
    s.exposure = dice.pick<float>({1e-4f, 1.0f, float(kMaxExposure)});
    s.ambient = glm::vec3(dice.pick<float>({0.0f, 0.05f, 1e6f}));
    if (dice.chance(0.3)) s.ambient = glm::vec3(dice.uniform(0, 2), dice.uniform(0, 2), dice.uniform(0, 2));
    scene.background.colour = glm::vec3(dice.uniform(0, 1), dice.uniform(0, 1), dice.uniform(0, 1)) *
                              dice.pick<float>({0.0f, 1.0f, 1e3f});
    s.energyConservation = dice.chance(0.5);
    s.shadow.mapSize = dice.pick<int>({64, 512, 2048});
    s.shadow.biasConstantM = dice.pick<float>({0.0f, 0.0005f, 1.0f});
    s.shadow.biasSlopeTexels = dice.pick<float>({0.0f, 2.0f, 1e3f});
    s.shadow.filter = dice.pick<ShadowFilter>(kShadowFilters.values());
    s.sss.enabled = dice.chance(0.9);
    s.sss.variant = dice.pick<SssVariant>(kSssVariants.values());
    s.sss.blur = dice.chance(0.5) ? SssBlur::Variant : dice.pick<SssBlur>(kSssBlurs.values());
    s.sss.taps = 2 * dice.pick<int>({1, 2, 3, 4, 6, 8, 16}) + 1;
    s.sss.bilateralDepthMm = dice.pick<float>({1e-4f, 1.0f, 1e4f});
    s.sss.controlDepthScalePerMm = dice.pick<float>({0.0f, 0.5f, 1e4f});
    s.sss.gaussians = dice.pick<int>({1, 3, 6, 8});
    s.sss.widthScale = dice.pick<float>({0.0f, 1e-3f, 1.0f, 10.0f, 1e4f});
    if (s.sss.widthScale > 100.0f || s.sss.taps > 30) note(c.description, "extreme SSS width or taps");
    s.sss.minWidthPx = dice.pick<float>({0.0f, 0.5f, 1e3f});
    s.sss.mix = dice.pick<float>({0.0f, 0.5f, 1.0f});
    {
        // The technique from dice of its own, so that every other value of a
        // seed stays what it was when the technique was not varied (the seeds
        // that once failed keep making the cases that failed).
        Dice techniqueDice(seed ^ 0x7ec4a1d5c0ffee11ull);
        s.sss.technique = techniqueDice.pick<SssTechnique>(kSssTechniques.values());
        s.sss.separableSamples = techniqueDice.pick<int>({kMinSeparableSamples, 17, kMaxSeparableSamples});
        s.sss.diskSamples = techniqueDice.pick<int>({kMinDiskSamples, 40, kMaxDiskSamples});
        if (s.sss.technique != SssTechnique::Gaussians)
            note(c.description, std::string("SSS technique ") + std::string(kSssTechniques.name(s.sss.technique)));
    }
    s.transmittance.enabled = dice.chance(0.8);
    s.transmittance.shrinkMm = dice.pick<float>({0.0f, 1.0f, 1e3f});
    s.transmittance.strength = dice.pick<float>({0.0f, 1.0f, 1e6f});
    s.ssao.enabled = dice.chance(0.7);
    s.ssao.samples = dice.pick<int>({8, 16, 128});
    s.ssao.radiusM = dice.pick<float>({1e-5f, 0.02f, 10.0f});
    s.ssao.blur = dice.chance(0.7);
    s.ts.taps = 2 * dice.pick<int>({1, 3, 8}) + 1;
    // Irradiance textures of 64-512 texels keep the cost down; 2048 rarely.
    s.ts.minSize = dice.pick<int>({kMinTsSize, 128, 256});
    s.ts.maxSize = dice.chance(0.05) ? 2048 : dice.pick<int>({256, 512});
    s.ts.tsm = dice.chance(0.7);
    s.ts.tsmStrength = dice.pick<float>({0.0f, 1.0f, 1e4f});
    s.ts.seamBlend = dice.pick<float>({0.0f, 2.0f, 100.0f});

    // Mostly small frames; 1 in 50 is 640x360 or 1280x720.
    if (dice.chance(0.02)) {
        const bool hd = dice.chance(0.5);
        c.width = hd ? 1280 : 640;
        c.height = hd ? 720 : 360;
    } else {
        c.width = dice.pick<int>({1, 17, 64, 96, 160});
        c.height = dice.pick<int>({1, 9, 36, 54, 90});
    }
    std::vector<Aov> aovs = kAovs.values();
    aovs.push_back(Aov::Final);  // the frame users see, twice as often
    c.aov = dice.pick<Aov>(aovs);
    c.frames = dice.pick<int>({1, 1, 2, 3, 4});
    c.cameraStepM = dice.direction() * dice.pick<float>({0.0f, 0.01f, 0.1f});
    c.lightStepDeg = dice.pick<float>({0.0f, 5.0f, 45.0f});
    if (c.frames > 1) note(c.description, std::to_string(c.frames) + " frames, camera and light moving");

    if (dice.chance(1.0 / 16.0)) {
        makeHostile(dice, c);
    } else if (dice.chance(0.25)) {
        c.path = CasePath::Loader;
        c.overrides = makeOverrides(dice, c.scene);
        note(c.description, "through the scene loader with " + std::to_string(c.overrides.size()) + " --set");
    }
    return c;
}

void advanceFrame(const StressCase& c, Scene& scene) {
    scene.camera.positionM += c.cameraStepM;
    scene.camera.targetM += c.cameraStepM;
    if (scene.lights.empty()) return;
    const glm::mat3 turn(glm::rotate(glm::mat4(1.0f), glm::radians(c.lightStepDeg), glm::vec3(0, 1, 0)));
    Light& light = scene.lights.front();
    light.direction = turn * light.direction;
    light.positionM = turn * light.positionM;
}

}  // namespace dermis::stress
