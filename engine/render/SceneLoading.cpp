#include "render/SceneLoading.h"

#include "core/Log.h"
#include "import/EnvironmentSource.h"
#include "import/ModelLoader.h"
#include "pose/CharacterPose.h"

namespace dermis {

Result<std::vector<Model>> loadSceneModels(const Scene& scene) {
    std::vector<Model> models;
    for (const Character& character : scene.characters) {
        log::info("loading character '" + character.name + "'");
        auto model = loadCharacterModel(character);
        if (!model.ok()) return model.error();
        if (model->mesh.indices.empty()) return makeError(character.name, "mesh has no triangles");
        if (Status names = checkMaterialNames(scene, models.size(), *model); !names) return names.error();
        auto clip = resolveAnimationClip(scene, models.size(), model->rig);
        if (!clip.ok()) return clip.error();
        models.push_back(std::move(*model));
    }
    return models;
}

Result<std::shared_ptr<const EnvironmentLight>> loadEnvironmentLight(const Environment& environment, size_t sceneLights) {
    auto map = loadEnvironmentSource(environment);
    if (!map.ok()) return map.error();
    log::info("environment '" + environment.source + "': " + std::to_string(map->width) + "x" + std::to_string(map->height));
    return splitEnvironmentLight(environment.source, std::move(*map), lightExtractionSettings(environment, sceneLights));
}

Status loadEnvironment(const Scene& scene, SceneGeometry& geometry) {
    const Environment& environment = scene.environment;
    // Without an environment the loaded light stays, for when the scene turns it back on.
    if (!environment.enabled()) return success();
    const LightExtractionSettings extraction = lightExtractionSettings(environment, scene.lights.size());
    const std::shared_ptr<const EnvironmentLight>& loaded = geometry.environmentLight();
    if (!loaded || loaded->source != environment.source) {
        auto light = loadEnvironmentLight(environment, scene.lights.size());
        if (!light.ok()) return light.error();
        geometry.setEnvironmentLight(std::move(*light));
    } else if (!(loaded->extraction == extraction)) {
        geometry.setEnvironmentLight(splitEnvironmentLight(environment.source, loaded->map, extraction));
    }
    return success();
}

}  // namespace dermis
