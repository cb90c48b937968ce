#include "stress/StressCases.h"

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
    glm::vec3 direction() {
        glm::vec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        return glm::length(d) < 1e-3f ? glm::vec3(0, -1, 0) : d;
    }

private:
    std::mt19937_64 mRng;
};

void note(std::string& description, const std::string& what) {
    if (!description.empty()) description += ", ";
    description += what;
}

Character makeCharacter(Dice& dice, const std::string& assets, int index, std::string& description) {
    Character c;
    c.name = "c" + std::to_string(index);
    const std::string mesh = dice.pick<std::string>({"plane", "sphere", "wedge", "sphere", "degenerate", "head"});
    if (mesh == "degenerate") {
        c.mesh.gltfPath = assets + "/degenerate.gltf";
        note(description, "degenerate and zero-area triangles, zero normals");
    } else {
        c.mesh.procedural = mesh;
    }
    if (mesh == "head") c.material.procedural = true;
    c.transform.translationM = glm::vec3(dice.uniform(-0.2f, 0.2f), dice.uniform(-0.1f, 0.1f), dice.uniform(-0.2f, 0.2f));
    c.transform.rotationDeg = glm::vec3(dice.uniform(-180, 180), dice.uniform(-180, 180), dice.uniform(-180, 180));
    c.transform.scale = dice.pick<float>({1.0f, 1.0f, 0.01f, 5.0f});
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
    light.colour = glm::vec3(dice.uniform(0, 1), dice.uniform(0, 1), dice.uniform(0, 1));
    light.intensity = dice.pick<float>({0.0f, 1.0f, 3.0f, 1e5f, 1e30f});
    if (light.intensity > 65504.0f) note(description, "light past fp16");
    light.spotInnerDeg = dice.uniform(0, 60);
    light.spotOuterDeg = light.spotInnerDeg + dice.pick<float>({0.0f, 5.0f, 20.0f});
    light.castsShadow = dice.chance(0.7);
    return light;
}

}  // namespace

StressCase makeStressCase(uint64_t seed, const std::string& assets) {
    Dice dice(seed);
    StressCase c;
    c.seed = seed;
    Scene& scene = c.scene;
    scene.path = "stress case " + std::to_string(seed);

    const int characters = dice.pick<int>({1, 1, 2, 3});
    for (int i = 0; i < characters; ++i) scene.characters.push_back(makeCharacter(dice, assets, i, c.description));

    const int lights = dice.pick<int>({0, 1, 2, 3, 64});
    if (lights == 0) note(c.description, "no lights");
    if (lights == 64) note(c.description, "64 lights");
    for (int i = 0; i < lights; ++i) scene.lights.push_back(makeLight(dice, c.description));

    Camera& camera = scene.camera;
    camera.nearM = dice.pick<float>({1e-4f, 0.01f, 0.05f, 0.5f});
    camera.farM = camera.nearM * dice.pick<float>({1.01f, 100.0f, 1e5f});
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
    s.exposure = dice.pick<float>({1e-4f, 1.0f, 1e4f});
    s.ambient = glm::vec3(dice.pick<float>({0.0f, 0.05f, 1e6f}));
    s.energyConservation = dice.chance(0.5);
    s.shadow.mapSize = dice.pick<int>({64, 512, 2048});
    s.shadow.biasConstantM = dice.pick<float>({0.0f, 0.0005f, 1.0f});
    s.shadow.biasSlopeTexels = dice.pick<float>({0.0f, 2.0f, 1e3f});
    s.shadow.filter = dice.pick<ShadowFilter>(kShadowFilters.values());
    s.sss.enabled = dice.chance(0.9);
    s.sss.blur = dice.pick<SssBlur>({SssBlur::Bilateral, SssBlur::Control, SssBlur::FetchOnly});
    s.sss.taps = 2 * dice.pick<int>({1, 2, 3, 4, 6, 8, 16}) + 1;
    s.sss.bilateralDepthMm = dice.pick<float>({1e-4f, 1.0f, 1e4f});
    s.sss.controlDepthScalePerMm = dice.pick<float>({0.0f, 0.5f, 1e4f});
    s.sss.gaussians = dice.pick<int>({1, 3, 6, 8});
    s.sss.widthScale = dice.pick<float>({0.0f, 1e-3f, 1.0f, 10.0f, 1e4f});
    if (s.sss.widthScale > 100.0f || s.sss.taps > 30) note(c.description, "extreme SSS width or taps");
    s.sss.minWidthPx = dice.pick<float>({0.0f, 0.5f, 1e3f});
    s.sss.mix = dice.pick<float>({0.0f, 0.5f, 1.0f});
    s.transmittance.enabled = dice.chance(0.8);
    s.transmittance.shrinkMm = dice.pick<float>({0.0f, 1.0f, 1e3f});
    s.transmittance.strength = dice.pick<float>({0.0f, 1.0f, 1e6f});
    s.ssao.enabled = dice.chance(0.7);
    s.ssao.samples = dice.pick<int>({8, 16, 128});
    s.ssao.radiusM = dice.pick<float>({1e-5f, 0.02f, 10.0f});
    s.ssao.blur = dice.chance(0.7);

    c.width = dice.pick<int>({1, 17, 64, 96});
    c.height = dice.pick<int>({1, 9, 36, 54});
    c.aov = dice.pick<Aov>({Aov::Final, Aov::Final, Aov::Diffuse, Aov::Irradiance, Aov::Specular, Aov::Transmittance,
                            Aov::Thickness, Aov::Ao, Aov::Depth, Aov::Normal});
    return c;
}

}  // namespace dermis::stress
