#include "reference/ReferenceDefinition.h"

#include "core/ContentHash.h"
#include "scene/SceneLoader.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <system_error>
#include <utility>

namespace dermis::reference {
namespace {

std::string digest(const std::string& text) { return hex16(fnv1a(text.data(), text.size())); }

// A file the scene names, one way whatever the working directory or the
// scene path's form (relative or absolute) the command was given.
void canonicalPaths(nlohmann::json& value) {
    static const std::set<std::string> kPathKeys = {"gltf",         "albedo_map",   "normal_map", "roughness_map",
                                                    "specular_map", "scatter_map", "source"};
    if (!value.is_structured()) return;
    for (auto item = value.begin(); item != value.end(); ++item) {
        const bool pathKey = value.is_object() && kPathKeys.count(item.key()) > 0;
        if (pathKey && item->is_string() && !item->get<std::string>().empty() && !isBuiltInEnvironment(item->get<std::string>())) {
            std::error_code ignored;
            *item = std::filesystem::weakly_canonical(std::filesystem::absolute(item->get<std::string>()), ignored).generic_string();
        } else {
            canonicalPaths(*item);
        }
    }
}

std::vector<std::pair<std::string, std::string>> parts(const Scene& scene) {
    Scene unplaced = scene;
    unplaced.path.clear();  // file paths as resolved (from the working directory), made canonical below
    nlohmann::json document = nlohmann::json::parse(sceneToJson(unplaced));
    canonicalPaths(document);
    // The environment as the reference reads it: the map, its intensity, rotation and background. How
    // the engine approximates it (occlusion, diffuse, specular, sh_bands, the extracted light) is the
    // engine's own, like SSAO: what a comparison with the reference measures.
    if (document.contains("environment")) {
        nlohmann::json& environment = document["environment"];
        for (const char* engineOnly : {"occlusion", "diffuse", "specular", "sh_bands", "extract_light", "extract_threshold"})
            environment.erase(engineOnly);
    }
    const auto section = [&](const char* key) { return document.contains(key) ? document[key].dump() : std::string(); };
    const RenderSettings& s = scene.settings;
    const nlohmann::json settings = {{"ambient", {s.ambient.x, s.ambient.y, s.ambient.z}},
                                     {"energy_conservation", s.energyConservation},
                                     {"sss", {{"enabled", s.sss.enabled}, {"width_scale", s.sss.widthScale}, {"mix", s.sss.mix}}}};
    return {{"camera", digest(section("camera"))},           {"lights", digest(section("lights"))},
            {"characters", digest(section("characters"))},   {"profiles", digest(section("profiles"))},
            {"environment", digest(section("environment"))}, {"settings", digest(settings.dump())}};
}

}  // namespace

std::string definitionRecord(const Scene& scene) {
    std::string record;
    for (const auto& [name, value] : parts(scene)) record += (record.empty() ? "" : ";") + name + "=" + value;
    return record;
}

std::vector<std::string> definitionMismatch(const std::string& record, const Scene& scene) {
    std::vector<std::string> differing;
    for (const auto& [name, value] : parts(scene)) {
        if (record.find(name + "=" + value) == std::string::npos) differing.push_back(name);
    }
    return differing;
}

}  // namespace dermis::reference
