#include "stress/InvariantFrame.h"

#include "stress/InvariantRays.h"

#include "gpu/UniformBlocks.h"

#include <map>
#include <random>

namespace dermis::stress {
namespace {

Result<Image> renderAov(Renderer& renderer, int width, int height, Aov aov) {
    if (const Status s = renderer.renderFrame({width, height, aov}); !s.ok()) return s.error();
    return renderer.readOutput();
}

struct FrameAovs {
    Image object, depth, albedo, diffuse, irradiance, transmittance, radiance, final;
};

Result<FrameAovs> renderAovs(Renderer& renderer, int width, int height) {
    FrameAovs f;
    const std::pair<Aov, Image*> wanted[] = {
        {Aov::Object, &f.object},         {Aov::Depth, &f.depth},       {Aov::Albedo, &f.albedo},
        {Aov::Diffuse, &f.diffuse},       {Aov::Irradiance, &f.irradiance},
        {Aov::Transmittance, &f.transmittance}, {Aov::Radiance, &f.radiance}, {Aov::Final, &f.final}};
    for (const auto& [aov, image] : wanted) {
        auto rendered = renderAov(renderer, width, height, aov);
        if (!rendered.ok()) return rendered.error();
        *image = std::move(*rendered);
    }
    return f;
}

int pixelsOf(const Image& object, int character) {
    int n = 0;
    for (int y = 0; y < object.height; ++y)
        for (int x = 0; x < object.width; ++x) n += objectAt(object, x, y) == character;
    return n;
}

void setCharacter(Image& image, const Image& object, int character, const glm::vec4& value) {
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (objectAt(object, x, y) == character) image.at(x, y) = value;
}

// The blur groups: screen space blurs each profile's pixels together
// (shaders/include/SssBlur.glsl, the stencil = profile slot), so characters
// sharing an SSS profile share a bound; every other character is its own.
std::vector<int> blurGroups(const Scene& scene, int* groups) {
    std::map<std::string, int> byProfile;
    std::vector<int> groupOf;
    *groups = 0;
    for (const Character& c : scene.characters) {
        const bool scatters = scene.settings.sss.enabled && c.material.profile != kOpaqueProfile;
        if (scatters && byProfile.count(c.material.profile)) {
            groupOf.push_back(byProfile[c.material.profile]);
            continue;
        }
        if (scatters) byProfile[c.material.profile] = *groups;
        groupOf.push_back((*groups)++);
    }
    return groupOf;
}

// In ts mode the TSM transmittance terms are added in the gather, outside
// the irradiance texture: the bound holds only without them.
bool tsTransmittanceMayAdd(const Scene& scene) {
    if (!scene.settings.transmittance.enabled) return false;
    for (const Light& l : scene.lights)
        if (l.castsShadow) return true;
    return false;
}

}  // namespace

Result<InvariantReport> checkFrameInvariants(Renderer& renderer, const Scene& scene, int width, int height,
                                             Plant plant) {
    renderer.setPassInspector({});
    auto aovs = renderAovs(renderer, width, height);
    if (!aovs.ok()) return aovs.error();
    FrameAovs& f = *aovs;
    auto sceneRays = SceneRays::create(scene);
    if (!sceneRays.ok()) return sceneRays.error();
    const std::vector<RaySample> rays = sceneRays->sample(width, height);
    const int characters = int(scene.characters.size());

    if (plant == Plant::Coverage) {
        int largest = -1, most = 0;
        for (int c = 0; c < characters; ++c) {
            const int n = pixelsOf(f.object, c);
            if (n > most) most = n, largest = c;
        }
        if (largest >= 0) setCharacter(f.object, f.object, largest, glm::vec4(0.0f, 0.0f, 0.0f, f.object.at(0, 0).a));
    }
    if (plant == Plant::Energy)
        for (glm::vec4& t : f.diffuse.texels) t = glm::vec4(glm::vec3(t) * 1.5f, t.a);
    if (plant == Plant::Black) {
        std::vector<int> lit(size_t(characters), 0);
        for (const RaySample& r : rays)
            if (r.lit && r.character >= 0) ++lit[size_t(r.character)];
        const int c = int(std::max_element(lit.begin(), lit.end()) - lit.begin());
        if (characters > 0) setCharacter(f.radiance, f.object, c, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }

    InvariantReport report;
    checkObjectCoversDepth(f.object, f.depth, characters, report[Invariant::Coverage]);
    checkRaysMatchObject(f.object, rays, characters, report[Invariant::Coverage]);

    const bool textureSpace = scene.settings.mode == SssMode::TextureSpace;
    if (!(textureSpace && tsTransmittanceMayAdd(scene))) {
        EnergyInputs energy;
        energy.diffuse = &f.diffuse;
        energy.albedo = &f.albedo;
        energy.object = &f.object;
        energy.mix = scene.settings.sss.mix;
        int groups = 0;
        energy.groupOf = blurGroups(scene, &groups);
        energy.groupBlurMax = largestBlurInput(f.irradiance, f.transmittance, f.object, energy.groupOf, groups);
        if (textureSpace) {
            auto textures = renderer.captureIrradianceTextures(kEnergyCaptureTexels);
            if (!textures.ok()) return textures.error();
            for (size_t c = 0; c < textures->size(); ++c) {
                glm::vec3& m = energy.groupBlurMax[size_t(energy.groupOf[c])];
                for (const glm::vec4& t : (*textures)[c].texels)
                    if (t.a > 0.0f) m = glm::max(m, glm::vec3(t));
            }
        }
        checkEnergy(energy, report[Invariant::Energy]);
    }
    checkNotBlack(f.object, f.albedo, f.diffuse, f.radiance, f.final, rays, scene.settings.exposure, characters,
                  report[Invariant::Black]);
    return report;
}

Scene makeSmoothLightingScene(uint64_t seed, SssMode mode) {
    std::mt19937_64 rng(seed * 0x2545F4914F6CDD1Dull + 7);
    auto uniform = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
    Scene scene;
    scene.path = "smooth-lighting case " + std::to_string(seed);
    Character sphere;
    sphere.name = "sphere";
    sphere.mesh.procedural = "sphere";
    sphere.material.profile = "skin";
    sphere.material.albedo = glm::vec3(uniform(0.3f, 1.0f), uniform(0.3f, 1.0f), uniform(0.3f, 1.0f));
    sphere.material.roughness = uniform(0.2f, 0.6f);
    sphere.transform.rotationDeg = glm::vec3(uniform(-180, 180), uniform(-180, 180), uniform(-180, 180));
    scene.characters.push_back(sphere);
    Light light;
    light.type = LightType::Directional;
    // From the camera's hemisphere, so that most of the visible disc is lit.
    light.direction = glm::vec3(uniform(-1, 1), uniform(-1, 1), -uniform(0.3f, 1.0f));
    light.intensity = uniform(1.0f, 3.0f);
    light.castsShadow = false;
    scene.lights.push_back(light);
    scene.camera.positionM = glm::vec3(0.0f, 0.0f, 0.4f);
    scene.camera.targetM = glm::vec3(0.0f);
    scene.camera.verticalFovDeg = 35.0f;
    scene.settings.mode = mode;
    scene.settings.ambient = glm::vec3(uniform(0.0f, 0.3f));
    scene.settings.ssao.enabled = false;
    scene.settings.transmittance.enabled = false;
    return scene;
}

Result<InvariantTally> checkScreenVsTextureCase(uint64_t seed, Plant plant, float* relative,
                                                std::shared_ptr<Programs> programs) {
    Image diffuse[2];
    Image object;
    const SssMode modes[2] = {SssMode::ScreenSpace, SssMode::TextureSpace};
    for (int m = 0; m < 2; ++m) {
        const Scene scene = makeSmoothLightingScene(seed, modes[m]);
        auto renderer = programs ? Renderer::create(scene, programs) : Renderer::create(scene);
        if (!renderer.ok()) return renderer.error();
        auto image = renderAov(**renderer, kSsTsFrame, kSsTsFrame, Aov::Diffuse);
        if (!image.ok()) return image.error();
        diffuse[m] = std::move(*image);
        if (m == 0) {
            auto ids = renderAov(**renderer, kSsTsFrame, kSsTsFrame, Aov::Object);
            if (!ids.ok()) return ids.error();
            object = std::move(*ids);
        }
    }
    if (plant == Plant::SsTs)
        for (glm::vec4& t : diffuse[1].texels) t = glm::vec4(glm::vec3(t) * 1.25f, t.a);
    InvariantTally tally;
    checkScreenMatchesTexture(object, diffuse[0], diffuse[1], tally, relative);
    return tally;
}

std::string addLight(Scene& scene, uint64_t seed) {
    const size_t lights = scene.lights.size();
    const bool hasEnvironment = !scene.environment.source.empty();
    switch (seed % 4) {
    case 1:
        if (lights > 0) {
            const size_t which = (seed / 4) % lights;
            scene.lights[which].intensity *= 8.0f;
            return "light " + std::to_string(which) + " eight times as bright";
        }
        break;
    case 2:
        if (lights < DERMIS_MAX_LIGHTS) {
            Light light;
            light.type = LightType::Directional;
            const glm::vec3 view = scene.camera.targetM - scene.camera.positionM;
            light.direction = glm::length(view) > 0.0f ? glm::normalize(view) : glm::vec3(0.0f, 0.0f, -1.0f);
            light.castsShadow = (seed / 4) % 2 == 0;
            scene.lights.push_back(light);
            return std::string("one more light from the camera, ") + (light.castsShadow ? "shadowed" : "unshadowed");
        }
        break;
    case 3:
        scene.settings.ambient += glm::vec3(0.2f);
        return "ambient + 0.2";
    default:
        break;
    }
    if (lights == 0 && !hasEnvironment) {
        scene.settings.ambient += glm::vec3(0.2f);
        return "ambient + 0.2 (no light to brighten)";
    }
    for (Light& light : scene.lights) light.intensity *= 2.0f;
    scene.environment.intensity *= 2.0f;
    return "every light and the environment twice as bright";
}

Result<InvariantTally> checkMoreLight(Renderer& renderer, Scene& scene, uint64_t seed, int width, int height,
                                      Plant plant) {
    renderer.setPassInspector({});
    auto before = renderAov(renderer, width, height, Aov::Radiance);
    if (!before.ok()) return before.error();
    const Scene unchanged = scene;  // the renderer keeps a reference to `scene` itself
    const std::string what = addLight(scene, seed);
    auto after = renderAov(renderer, width, height, Aov::Radiance);
    scene = unchanged;
    if (!after.ok()) return after.error();
    if (plant == Plant::MoreLight)
        for (glm::vec4& t : after->texels) t = glm::vec4(glm::vec3(t) * 0.9f, t.a);
    InvariantTally tally;
    checkMoreLightDarkensNothing(*before, *after, what, tally);
    return tally;
}

Result<InvariantReport> checkCaseInvariants(Renderer& renderer, Scene& scene, const StressCase& c, Plant plant,
                                            std::shared_ptr<Programs> programs) {
    auto report = checkFrameInvariants(renderer, scene, c.width, c.height, plant);
    if (!report.ok()) return report;
    auto moreLight = checkMoreLight(renderer, scene, c.seed, c.width, c.height, plant);
    if (!moreLight.ok()) return moreLight.error();
    (*report)[Invariant::MoreLight].add(*moreLight);
    if (c.seed % kSsTsEvery != 0) return report;
    auto ssTs = checkScreenVsTextureCase(c.seed, plant, nullptr, std::move(programs));
    if (!ssTs.ok()) return ssTs.error();
    (*report)[Invariant::SsTs].add(*ssTs);
    return report;
}

}  // namespace dermis::stress
