#include "render/SceneLoading.h"

#include "core/Log.h"
#include "import/EnvironmentSource.h"
#include "import/ModelLoader.h"
#include "mesh/LodNormalMaps.h"
#include "mesh/MeshLod.h"
#include "mesh/MeshLodCache.h"
#include "pose/CharacterPose.h"
#include "scene/SceneLoader.h"

#include <chrono>
#include <cstdio>
#include <map>

namespace dermis {

namespace {

// The model's levels of detail, made once per distinct mesh in the scene (two
// models may share a mesh with different materials), and cached on disk (mesh/MeshLodCache.h).
void addLevelsOfDetail(Model& model, std::map<uint64_t, std::vector<LodLevel>>& made) {
    const uint64_t key = lodCacheKey(model.mesh, model.drawRanges());
    if (auto found = made.find(key); found != made.end()) {
        model.lods = found->second;
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    bool fromCache = false;
    model.lods = loadOrMakeLodLevels(model.mesh, model.drawRanges(), &fromCache);
    if (!model.lods.empty()) {
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        std::string levels;
        for (const LodLevel& level : model.lods) levels += " " + std::to_string(level.triangleCount());
        char line[160];
        std::snprintf(line, sizeof line, "levels of detail of %zu triangles:%s triangles (%.0f ms%s)",
                      model.mesh.triangleCount(), levels.c_str(), ms, fromCache ? ", from the cache" : "");
        log::info(line);
    }
    made.emplace(key, model.lods);
}

// What loadCharacterModel reads of a character: all of it but its name and
// where and how it moves.
std::string modelKey(const Character& character) {
    Scene alone;
    Character loaded = character;
    loaded.name.clear();
    loaded.transform = {};
    loaded.ssao = {};
    loaded.animation = {};
    alone.characters.push_back(std::move(loaded));
    return sceneToJson(alone);
}

}  // namespace

Result<SceneModels> loadSharedSceneModels(const Scene& scene) {
    SceneModels models;
    std::map<uint64_t, std::vector<LodLevel>> levelsOfDetail;
    std::map<std::string, size_t> loaded;  // model key -> the first character with it
    for (const Character& character : scene.characters) {
        const size_t index = models.size();
        std::shared_ptr<const Model> model;
        const std::string key = modelKey(character);
        if (auto found = loaded.find(key); found != loaded.end()) {
            model = models[found->second];
        } else {
            log::info("loading character '" + character.name + "'");
            auto made = loadCharacterModel(character);
            if (!made.ok()) {
                const bool gltf = !character.mesh.gltfPath.empty() && made.error().where == character.mesh.gltfPath;
                return atSceneKey(scene, "/characters/" + std::to_string(index) + (gltf ? "/mesh/gltf" : ""), made.error());
            }
            if (made->mesh.indices.empty()) return makeError(character.name, "mesh has no triangles");
            // Levels only for a scene that draws them: measuring them and baking their
            // normal maps takes seconds per distinct mesh (docs/crowds.md).
            if (scene.settings.lod.maxErrorPx > 0.0f) addLevelsOfDetail(*made, levelsOfDetail);
            if (!made->lods.empty()) {
                const auto start = std::chrono::steady_clock::now();
                bakeLodNormalMaps(*made, character.material.flipV);
                const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
                log::info("levels' normal maps baked (" + std::to_string(int(ms)) + " ms)");
            }
            model = std::make_shared<const Model>(std::move(*made));
            loaded.emplace(key, index);
        }
        if (Status names = checkMaterialNames(scene, index, *model); !names) return names.error();
        auto clip = resolveAnimationClip(scene, index, model->rig);
        if (!clip.ok()) return clip.error();
        models.push_back(std::move(model));
    }
    if (loaded.size() < models.size()) {
        log::info(std::to_string(models.size()) + " characters share " + std::to_string(loaded.size()) + " models");
    }
    return models;
}

Result<std::vector<Model>> loadSceneModels(const Scene& scene) {
    auto shared = loadSharedSceneModels(scene);
    if (!shared.ok()) return shared.error();
    std::vector<Model> models;
    for (const std::shared_ptr<const Model>& model : *shared) models.push_back(*model);
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
        if (!light.ok()) return atSceneKey(scene, "/environment/source", light.error());
        geometry.setEnvironmentLight(std::move(*light));
    } else if (!(loaded->extraction == extraction)) {
        geometry.setEnvironmentLight(splitEnvironmentLight(environment.source, loaded->map, extraction));
    }
    return success();
}

}  // namespace dermis
