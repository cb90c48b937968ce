// sceneToJson (declared in SceneLoader.h): the writing half of the format.

#include "scene/SceneLoader.h"

#include "scene/ScenePaths.h"
#include "scene/SettingsFields.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdlib>

namespace dermis {

namespace {

// Keys in the order the format documentation lists them.
using Json = nlohmann::ordered_json;

// A float as the shortest decimal that reads back to the same float, so that
// the file says 0.05 rather than 0.05000000074505806.
Json number(float value) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof(buffer) - 1, value).ptr;
    *end = '\0';
    const double shortest = std::strtod(buffer, nullptr);
    // The reader converts the parsed double to float; in the rare case where
    // that double rounding differs, write the float's exact value instead.
    return static_cast<float>(shortest) == value ? Json(shortest) : Json(static_cast<double>(value));
}

Json vec3(const glm::vec3& v) {
    return Json::array({number(v.x), number(v.y), number(v.z)});
}

template <typename E, size_t N>
Json name(const EnumTable<E, N>& table, E value) {
    return Json(std::string(table.name(value)));
}

Json cameraJson(const Camera& camera) {
    Json j;
    j["position_m"] = vec3(camera.positionM);
    j["target_m"] = vec3(camera.targetM);
    j["up"] = vec3(camera.up);
    j["vertical_fov_deg"] = number(camera.verticalFovDeg);
    j["near_m"] = number(camera.nearM);
    j["far_m"] = number(camera.farM);
    return j;
}

Json lightJson(const Light& light) {
    Json j;
    j["type"] = name(kLightTypes, light.type);
    j["position_m"] = vec3(light.positionM);
    j["direction"] = vec3(light.direction);
    j["colour"] = vec3(light.colour);
    j["intensity"] = number(light.intensity);
    j["spot_inner_deg"] = number(light.spotInnerDeg);
    j["spot_outer_deg"] = number(light.spotOuterDeg);
    j["shadow"] = light.castsShadow;
    j["angular_diameter_deg"] = number(light.angularDiameterDeg);
    j["radius_m"] = number(light.radiusM);
    return j;
}

Json materialJson(const Material& m, const std::string& sceneFile) {
    Json material;
    material["albedo_map"] = relativeScenePath(sceneFile, m.albedoMap);
    material["normal_map"] = relativeScenePath(sceneFile, m.normalMap);
    material["roughness_map"] = relativeScenePath(sceneFile, m.roughnessMap);
    material["specular_map"] = relativeScenePath(sceneFile, m.specularMap);
    material["scatter_map"] = relativeScenePath(sceneFile, m.scatterMap);
    material["use_normal_map"] = m.useNormalMap;
    material["flip_v"] = m.flipV;
    material["procedural"] = m.procedural;
    material["albedo"] = vec3(m.albedo);
    material["roughness"] = number(m.roughness);
    material["rho_s"] = number(m.rhoS);
    material["width_scale"] = number(m.widthScale);
    material["scatter"] = number(m.scatter);
    material["profile"] = m.profile;
    return material;
}

Json profileJson(const DiffusionProfile& profile) {
    Json gaussians = Json::array();
    for (const ProfileGaussian& g : profile.gaussians())
        gaussians.push_back(Json{{"variance_mm2", number(g.varianceMm2)}, {"weights", vec3(g.weight)}});
    return Json{{"gaussians", std::move(gaussians)}};
}

Json characterJson(const Character& character, const std::string& sceneFile) {
    Json transform;
    transform["translation_m"] = vec3(character.transform.translationM);
    transform["rotation_deg"] = vec3(character.transform.rotationDeg);
    transform["scale"] = number(character.transform.scale);

    Json mesh = Json::object();
    if (!character.mesh.gltfPath.empty()) {
        mesh["gltf"] = relativeScenePath(sceneFile, character.mesh.gltfPath);
    } else {
        mesh["procedural"] = character.mesh.procedural;
    }

    Json j;
    j["material"] = materialJson(character.material, sceneFile);
    if (!character.materials.empty()) {
        Json materials = Json::object();
        for (const auto& [name, material] : character.materials) materials[name] = materialJson(material, sceneFile);
        j["materials"] = std::move(materials);
    }
    j["name"] = character.name;
    j["transform"] = std::move(transform);
    j["mesh"] = std::move(mesh);
    j["metres_per_unit"] = number(character.metresPerUnit);
    j["ssao"] = Json{{"radius_m", number(character.ssao.radiusM)}, {"samples", character.ssao.samples}};
    const CharacterAnimation& a = character.animation;
    j["animation"] = Json{{"clip", a.clip}, {"time_s", number(a.timeS)}, {"speed", number(a.speed)}, {"loop", a.loop}};
    return j;
}

// Writes the fields a visit lists (SettingsFields.h) into one JSON object.
class FieldWriter {
public:
    FieldWriter(Json& out, const std::string& sceneFile) : mOut(out), mSceneFile(sceneFile) {}

    void number(const char* key, float value, const Range&) { mOut[key] = dermis::number(value); }
    void integer(const char* key, int value, const Range&) { mOut[key] = value; }
    void rule(const char* key, int value, const IntegerRule&) { mOut[key] = value; }
    void boolean(const char* key, bool value) { mOut[key] = value; }
    void vec3(const char* key, const glm::vec3& value, const Range&) { mOut[key] = dermis::vec3(value); }
    void path(const char* key, const std::string& value) { mOut[key] = relativeScenePath(mSceneFile, value); }
    template <typename E, size_t N>
    void choice(const char* key, const EnumTable<E, N>& table, E value) {
        mOut[key] = name(table, value);
    }
    template <typename G, typename Visit>
    void group(const char* key, const G& group, Visit&& visit) {
        Json object;
        FieldWriter writer(object, mSceneFile);
        visit(group, writer);
        mOut[key] = std::move(object);
    }

private:
    Json& mOut;
    const std::string& mSceneFile;
};

Json environmentJson(const Environment& e, const std::string& sceneFile) {
    const std::string source = isBuiltInEnvironment(e.source) ? e.source : relativeScenePath(sceneFile, e.source);
    return Json{{"source", source},
                {"intensity", number(e.intensity)},
                {"rotation", Json{{"axis", vec3(e.rotation.axis)},
                                  {"angle_deg", number(e.rotation.angleDeg)},
                                  {"speed_deg_per_s", number(e.rotation.speedDegPerS)}}},
                {"background", e.background},
                {"occlusion", name(kEnvironmentOcclusions, e.occlusion)},
                {"specular", name(kEnvironmentSpeculars, e.specular)},
                {"diffuse", name(kEnvironmentDiffuses, e.diffuse)},
                {"sh_bands", e.shBands},
                {"extract_light", name(kEnvironmentLightExtractions, e.extractLight)},
                {"extract_threshold", number(e.extractThreshold)}};
}

Json settingsJson(const RenderSettings& settings, const std::string& sceneFile) {
    Json j;
    FieldWriter writer(j, sceneFile);
    visitSettingsFields(settings, writer);
    return j;
}

// nlohmann's pretty printer puts every array element on its own line; vectors
// read better as [0.1, 0.2, 0.3]. Collapses arrays that hold only numbers,
// leaving string contents alone.
std::string collapseNumberArrays(const std::string& pretty) {
    std::string out;
    out.reserve(pretty.size());
    size_t i = 0;
    while (i < pretty.size()) {
        if (pretty[i] == '"') {
            size_t end = i + 1;
            while (end < pretty.size() && pretty[end] != '"') {
                end += pretty[end] == '\\' ? 2 : 1;
            }
            end = std::min(end + 1, pretty.size());
            out.append(pretty, i, end - i);
            i = end;
            continue;
        }
        const size_t close = pretty[i] == '[' ? pretty.find(']', i) : std::string::npos;
        const bool numbersOnly =
            close != std::string::npos && pretty.find_first_not_of("0123456789.-+eE, \n", i + 1) >= close;
        if (!numbersOnly) {
            out += pretty[i++];
            continue;
        }
        for (size_t k = i; k <= close; ++k) {
            if (pretty[k] != ' ' && pretty[k] != '\n') {
                out += pretty[k];
                if (pretty[k] == ',') {
                    out += ' ';
                }
            }
        }
        i = close + 1;
    }
    return out;
}

}  // namespace

std::string sceneToJson(const Scene& scene) {
    Json root;
    root["camera"] = cameraJson(scene.camera);
    root["lights"] = Json::array();
    for (const Light& light : scene.lights) {
        root["lights"].push_back(lightJson(light));
    }
    root["characters"] = Json::array();
    for (const Character& character : scene.characters) {
        root["characters"].push_back(characterJson(character, scene.path));
    }
    if (!scene.profiles.empty()) {
        Json profiles = Json::object();
        for (const DiffusionProfile& profile : scene.profiles) profiles[profile.name()] = profileJson(profile);
        root["profiles"] = std::move(profiles);
    }
    root["background"] = Json{{"colour", vec3(scene.background.colour)}};
    if (scene.environment.enabled()) root["environment"] = environmentJson(scene.environment, scene.path);
    root["settings"] = settingsJson(scene.settings, scene.path);
    // Replace, not throw, on invalid UTF-8 in names or paths.
    return collapseNumberArrays(root.dump(2, ' ', false, Json::error_handler_t::replace)) + "\n";
}

}  // namespace dermis
