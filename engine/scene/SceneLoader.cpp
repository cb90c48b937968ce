#include "scene/SceneLoader.h"

#include "procedural/Procedural.h"
#include "sss/BurleyProfile.h"
#include "sss/DiffusionProfile.h"

#include "core/Limits.h"
#include "scene/JsonReader.h"
#include "scene/ScenePaths.h"
#include "scene/SettingsFields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>

namespace dermis {

namespace {

using nlohmann::json;

// Gaussians of a scene's Burley profile: as many as the built-in skin profile,
// so that the d'Eon chain and texture space blur it alike.
constexpr int kBurleySceneGaussians = 6;

// A direction within this of unit length is kept as written, so that a
// direction the loader normalised reads back bit-identical (normalising twice
// can move the last bit).
constexpr double kUnitLengthTolerance = 1e-6;
constexpr double kParallelTolerance = 1e-6;
// A limit on a ratio of two floats holds to their rounding (2^-24 each), with room.
constexpr double kFloatRatioTolerance = 1e-6;


double length(const glm::vec3& v) {
    const double x = v.x, y = v.y, z = v.z;
    return std::sqrt(x * x + y * y + z * z);
}

glm::dvec3 normalised(const glm::vec3& v) {
    return glm::dvec3(v) / length(v);
}

// A name from `table`, stored as its enum value.
template <typename E, size_t N>
void choice(JsonObject& object, const char* key, const EnumTable<E, N>& table, E& out) {
    int index = -1;
    object.choice(key, std::string(table.noun()).c_str(), table.names(), index);
    if (index >= 0) {
        out = table.begin()[index].value;
    }
}

// A product or ratio of two float values, to `digits` significant digits:
// 3 where the float rounding of the factors is noise, 7 for a ratio next to
// a limit (100001, not 1e+05).
std::string formatSignificantForMessage(double x, int digits) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    return text;
}

const Range kWorldCoordinates = Range::closed(-kMaxWorldCoordinateM, kMaxWorldCoordinateM);

void readCamera(JsonObject& root, Camera& camera) {
    const json* value = root.member("camera");
    if (value == nullptr) {
        return;
    }
    JsonObject object(root.context(), *value, root.pointer("camera"),
                      {"position_m", "target_m", "up", "vertical_fov_deg", "near_m", "far_m"});
    object.vec3("position_m", camera.positionM, kWorldCoordinates);
    object.vec3("target_m", camera.targetM, kWorldCoordinates);
    object.vec3("up", camera.up);
    object.number("vertical_fov_deg", camera.verticalFovDeg, Range::closed(kMinVerticalFovDeg, kMaxVerticalFovDeg));
    object.number("near_m", camera.nearM, Range::atLeast(kMinNearM));
    object.number("far_m", camera.farM, Range::above(0.0));

    JsonContext& context = root.context();
    if (context.failed()) {
        return;
    }
    context.check(camera.nearM < camera.farM, object.pointer("near_m"),
                  "must be less than far_m (" + formatNumberForMessage(camera.farM) + "), got " +
                      formatNumberForMessage(camera.nearM));
    // The ratio of the two floats as written: 1000 / 0.01 is 1e5 in decimals but 100000.002 in floats.
    const double farOverNear = double(camera.farM) / double(camera.nearM);
    context.check(farOverNear <= kMaxFarOverNear * (1.0 + kFloatRatioTolerance), object.pointer("far_m"),
                  "must be at most " + formatNumberForMessage(kMaxFarOverNear) + " x near_m (depth precision), got " +
                      formatSignificantForMessage(farOverNear, 7) + " x");
    context.check(length(camera.targetM - camera.positionM) >= kMinCameraTargetDistanceM, object.pointer("target_m"),
                  "must be at least " + formatNumberForMessage(kMinCameraTargetDistanceM) +
                      " m from position_m (the camera needs a view direction)");
    if (!context.check(length(camera.up) > 0.0, object.pointer("up"), "must not be the zero vector") ||
        context.failed()) {
        return;
    }
    const glm::dvec3 view = normalised(camera.targetM - camera.positionM);
    context.check(glm::length(glm::cross(view, normalised(camera.up))) > kParallelTolerance, object.pointer("up"),
                  "must not be parallel to the view direction (target_m - position_m)");
    // Stored at unit length: a float lookAt of an up 1e-30 or 3e38 long under- or overflowed.
    if (std::fabs(length(camera.up) - 1.0) > kUnitLengthTolerance) camera.up = glm::vec3(normalised(camera.up));
}

void readLight(JsonContext& context, const json& value, const std::string& pointer, Light& light) {
    JsonObject object(
        context, value, pointer,
        {"type", "position_m", "direction", "colour", "intensity", "spot_inner_deg", "spot_outer_deg", "shadow",
         "angular_diameter_deg", "radius_m"});
    choice(object, "type", kLightTypes, light.type);
    object.vec3("position_m", light.positionM, kWorldCoordinates);
    object.vec3("direction", light.direction);
    object.vec3("colour", light.colour, Range::atLeast(0.0));
    object.number("intensity", light.intensity, Range::atLeast(0.0));
    object.number("spot_inner_deg", light.spotInnerDeg, Range::rightOpen(0.0, 90.0));
    object.number("spot_outer_deg", light.spotOuterDeg, Range::rightOpen(0.0, 90.0));
    object.boolean("shadow", light.castsShadow);
    object.number("angular_diameter_deg", light.angularDiameterDeg,
                  Range::rightOpen(0.0, kMaxLightAngularDiameterDeg));
    object.number("radius_m", light.radiusM, Range::rightOpen(0.0, kMaxLightRadiusM));
    if (context.failed()) {
        return;
    }
    const double brightest = double(std::max({light.colour.r, light.colour.g, light.colour.b})) * light.intensity;
    context.check(brightest <= double(float(kMaxLightRadiance)), object.pointer("intensity"),
                  "colour x intensity must be at most " + formatNumberForMessage(kMaxLightRadiance) +
                      " per channel (float range), got " + formatSignificantForMessage(brightest, 3));
    context.check(light.spotInnerDeg <= light.spotOuterDeg, object.pointer("spot_inner_deg"),
                  "must be <= spot_outer_deg (" + formatNumberForMessage(light.spotOuterDeg) + "), got " +
                      formatNumberForMessage(light.spotInnerDeg));
    const double directionLength = length(light.direction);
    if (context.check(directionLength > 0.0, object.pointer("direction"), "must not be the zero vector") &&
        std::fabs(directionLength - 1.0) > kUnitLengthTolerance) {
        light.direction = glm::vec3(normalised(light.direction));
    }
}

void readTransform(JsonObject& parent, Transform& transform) {
    const json* value = parent.member("transform");
    if (value == nullptr) {
        return;
    }
    JsonObject object(parent.context(), *value, parent.pointer("transform"),
                      {"translation_m", "rotation_deg", "scale"});
    object.vec3("translation_m", transform.translationM, kWorldCoordinates);
    object.vec3("rotation_deg", transform.rotationDeg);
    object.number("scale", transform.scale, Range::above(0.0));
}

// A name from a set the engine defines (diffusion profiles, procedural
// meshes): checked here, so that the error names the file and the key.
void checkName(JsonObject& object, const char* key, const std::string& name, const std::vector<std::string>& known,
               const std::string& noun) {
    if (!object.has(key) || std::find(known.begin(), known.end(), name) != known.end()) return;
    object.context().check(false, object.pointer(key),
                           "unknown " + noun + " " + quoteForMessage(name) + suggestionForMessage(name, known) + " (known: " +
                               listForMessage(known, "or") + ")");
}

void readMesh(JsonObject& parent, const std::string& sceneFile, MeshSource& mesh) {
    const json* value = parent.member("mesh");
    JsonContext& context = parent.context();
    if (context.failed()) {
        return;
    }
    if (value == nullptr) {
        context.fail(parent.pointer(), "missing required key \"mesh\"");
        return;
    }
    JsonObject object(context, *value, parent.pointer("mesh"), {"procedural", "gltf"});
    if (context.failed()) {
        return;
    }
    const bool procedural = object.has("procedural");
    const bool gltf = object.has("gltf");
    if (!context.check(procedural != gltf, object.pointer(),
                       procedural
                           ? "give exactly one of \"procedural\" and \"gltf\", not both"
                           : "missing mesh source: give \"procedural\" (a built-in mesh name) or \"gltf\" (a file)")) {
        return;
    }
    object.string("procedural", mesh.procedural, false);
    if (procedural) checkName(object, "procedural", mesh.procedural, proceduralModelNames(), "procedural mesh");
    object.string("gltf", mesh.gltfPath, false);
    mesh.gltfPath = resolveScenePath(sceneFile, mesh.gltfPath);
}

const std::vector<std::string> kMaterialKeys = {"albedo_map",  "normal_map",    "use_normal_map", "flip_v",
                                                 "procedural",  "albedo",        "roughness",      "rho_s",
                                                 "profile",     "width_scale",   "roughness_map",  "specular_map",
                                                 "scatter",     "scatter_map"};

void readMaterialFields(JsonObject& object, const std::string& sceneFile, const std::vector<std::string>& profiles,
                        Material& material) {
    object.string("albedo_map", material.albedoMap);
    object.string("normal_map", material.normalMap);
    object.string("roughness_map", material.roughnessMap);
    object.string("specular_map", material.specularMap);
    object.string("scatter_map", material.scatterMap);
    for (std::string* path : {&material.albedoMap, &material.normalMap, &material.roughnessMap, &material.specularMap,
                              &material.scatterMap})
        *path = resolveScenePath(sceneFile, *path);
    object.boolean("use_normal_map", material.useNormalMap);
    object.boolean("flip_v", material.flipV);
    object.boolean("procedural", material.procedural);
    object.vec3("albedo", material.albedo, Range::closed(0.0, 1.0));
    object.number("roughness", material.roughness, Range::leftOpen(0.0, 1.0));
    object.number("rho_s", material.rhoS, Range::closed(0.0, 1.0));
    object.number("width_scale", material.widthScale, Range::leftOpen(0.0, kMaxWidthScale));
    object.number("scatter", material.scatter, Range::closed(0.0, 1.0));
    material.scatteringGiven = object.has("profile") || object.has("scatter") || object.has("scatter_map");
    object.string("profile", material.profile, false);
    checkName(object, "profile", material.profile, profiles, "diffusion profile");
}

void readMaterial(JsonObject& parent, const std::string& sceneFile, const std::vector<std::string>& profiles,
                  Material& material) {
    const json* value = parent.member("material");
    if (value == nullptr) {
        return;
    }
    JsonObject object(parent.context(), *value, parent.pointer("material"), kMaterialKeys);
    readMaterialFields(object, sceneFile, profiles, material);
}

// The object at `key` whose members are named by the file (glTF material
// names, profile names), or null when absent or not an object (an error).
const json* namedObjects(JsonObject& parent, const char* key, const std::string& what) {
    const json* value = parent.member(key);
    if (value == nullptr || parent.context().failed()) {
        return nullptr;
    }
    const bool isObject = parent.context().check(value->is_object(), parent.pointer(key),
                                                 "must be an object of " + what + ", got " + jsonTypeForMessage(*value));
    return isObject ? value : nullptr;
}

// Per glTF material name, a material that starts as the character's own.
void readMaterialOverrides(JsonObject& parent, const std::string& sceneFile, const std::vector<std::string>& profiles,
                           Character& character) {
    const json* value = namedObjects(parent, "materials", "materials by glTF material name or \"#index\"");
    JsonContext& context = parent.context();
    if (value == nullptr) {
        return;
    }
    for (const auto& [name, entry] : value->items()) {
        Material material = character.material;
        JsonObject object(context, entry, parent.pointer("materials") + "/" + jsonPointerSegment(name), kMaterialKeys);
        readMaterialFields(object, sceneFile, profiles, material);
        character.materials[name] = material;
    }
}

// Scene-level user profiles: 1..DERMIS_MAX_PROFILE_GAUSSIANS Gaussians each,
// variances > 0 and increasing, RGB weights >= 0 summing to 1 per channel.
constexpr double kProfileWeightSumTolerance = 1e-3;

// A profile given as Burley's normalized diffusion (Christensen & Burley 2015):
// its six-Gaussian fit (sss/BurleyProfile.h), which every technique but the disk
// uses; the profile keeps the parameters, and the disk samples them exactly.
void readBurleyProfile(JsonObject& object, const std::string& name, std::vector<DiffusionProfile>& out) {
    JsonContext& context = object.context();
    JsonObject burley(context, *object.member("burley"), object.pointer("burley"), {"albedo", "mean_free_path_mm"});
    if (!context.check(burley.has("albedo") && burley.has("mean_free_path_mm"), object.pointer("burley"),
                       "needs \"albedo\" and \"mean_free_path_mm\"")) {
        return;
    }
    glm::vec3 albedo(0.0f), meanFreePathMm(0.0f);
    burley.vec3("albedo", albedo, Range::closed(0.0, 1.0));
    burley.vec3("mean_free_path_mm", meanFreePathMm, Range::above(0.0));
    if (context.failed()) return;
    auto profile = fitBurleyGaussians({albedo, meanFreePathMm}, kBurleySceneGaussians, name);
    if (!profile.ok()) {
        char values[160];
        std::snprintf(values, sizeof values, "albedo [%g, %g, %g], mean_free_path_mm [%g, %g, %g]: ", albedo.r, albedo.g,
                      albedo.b, meanFreePathMm.r, meanFreePathMm.g, meanFreePathMm.b);
        context.fail(object.pointer("burley"), values + profile.error().what);
        return;
    }
    out.push_back(std::move(*profile));
}

void readProfile(JsonContext& context, const json& value, const std::string& pointer, const std::string& name,
                 std::vector<DiffusionProfile>& out) {
    JsonObject object(context, value, pointer, {"gaussians", "burley"});
    if (object.has("burley")) {
        if (context.check(!object.has("gaussians"), pointer, "give \"gaussians\" or \"burley\", not both")) {
            readBurleyProfile(object, name, out);
        }
        return;
    }
    const json* list = object.array("gaussians", kMaxProfileGaussians, "Gaussians");
    if (context.failed()) return;
    if (!context.check(list != nullptr && !list->empty(), object.pointer("gaussians"),
                       "give 1 to " + std::to_string(kMaxProfileGaussians) + " Gaussians")) {
        return;
    }
    std::vector<ProfileGaussian> gaussians(list->size());
    glm::dvec3 sums(0.0);
    for (size_t i = 0; i < list->size() && !context.failed(); ++i) {
        const std::string at = object.pointer("gaussians") + "/" + std::to_string(i);
        JsonObject gaussian(context, (*list)[i], at, {"variance_mm2", "weights"});
        if (!context.check(gaussian.has("variance_mm2") && gaussian.has("weights"), at,
                           "needs \"variance_mm2\" and \"weights\"")) {
            return;
        }
        gaussian.number("variance_mm2", gaussians[i].varianceMm2, Range::above(0.0));
        gaussian.vec3("weights", gaussians[i].weight, Range::closed(0.0, 1.0));
        if (i > 0 && !context.failed()) {
            context.check(gaussians[i].varianceMm2 > gaussians[i - 1].varianceMm2, gaussian.pointer("variance_mm2"),
                          "variances must increase strictly, got " + formatNumberForMessage(gaussians[i].varianceMm2) +
                              " after " + formatNumberForMessage(gaussians[i - 1].varianceMm2));
        }
        sums += glm::dvec3(gaussians[i].weight);
    }
    if (context.failed()) return;
    for (int c = 0; c < 3; ++c) {
        const char* channel[] = {"red", "green", "blue"};
        char sum[32];  // 5 digits: enough to show a sum just outside the tolerance, none of the float noise
        std::snprintf(sum, sizeof sum, "%.5g", sums[c]);
        if (!context.check(std::fabs(sums[c] - 1.0) <= kProfileWeightSumTolerance, object.pointer("gaussians"),
                           std::string("the ") + channel[c] + " weights sum to " + sum +
                               "; each channel must sum to 1 (within 1e-3)")) {
            return;
        }
    }
    auto profile = DiffusionProfile::create(name, std::move(gaussians));
    if (!context.check(profile.ok(), pointer, profile.ok() ? "" : profile.error().what)) return;
    out.push_back(std::move(*profile));
}

void readProfiles(JsonObject& root, std::vector<DiffusionProfile>& out) {
    const json* value = namedObjects(root, "profiles", "profiles by name");
    JsonContext& context = root.context();
    if (value == nullptr) {
        return;
    }
    std::vector<std::string> builtins = profileNames();
    builtins.emplace_back(kOpaqueProfile);
    for (const auto& [name, entry] : value->items()) {
        const std::string pointer = root.pointer("profiles") + "/" + jsonPointerSegment(name);
        if (!context.check(!name.empty() && std::find(builtins.begin(), builtins.end(), name) == builtins.end(),
                           pointer,
                           "a user profile may not be named " + quoteForMessage(name) + " (built in: " +
                               listForMessage(builtins, "and") + ")")) {
            return;
        }
        readProfile(context, entry, pointer, name, out);
        if (context.failed()) return;
    }
}

// An integer that must also satisfy `valid` (odd, or 0 as "unset"): one message
// for every way of missing, as the range alone would not say it all.
void constrainedInteger(JsonObject& object, const char* key, int& out, bool (*valid)(int),
                        const std::string& requirement) {
    int value = out;
    object.integer(key, value);
    if (object.has(key) &&
        object.context().check(valid(value), object.pointer(key), requirement + ", got " + std::to_string(value))) {
        out = value;
    }
}

bool isSsaoSampleCount(int samples) {
    return samples >= kMinSsaoSamples && samples <= kMaxSsaoSamples;
}

void readCharacterSsao(JsonObject& parent, CharacterSsao& ssao) {
    const json* value = parent.member("ssao");
    if (value == nullptr) {
        return;
    }
    JsonObject object(parent.context(), *value, parent.pointer("ssao"), {"radius_m", "samples"});
    object.number("radius_m", ssao.radiusM, Range::atLeast(0.0));
    constrainedInteger(
        object, "samples", ssao.samples, [](int n) { return n == 0 || isSsaoSampleCount(n); },
        "must be 0 (use settings.ssao.samples) or in [" + std::to_string(kMinSsaoSamples) + ", " +
            std::to_string(kMaxSsaoSamples) + "]");
}

void readCharacterAnimation(JsonObject& parent, CharacterAnimation& animation) {
    const json* value = parent.member("animation");
    if (value == nullptr) {
        return;
    }
    JsonObject object(parent.context(), *value, parent.pointer("animation"), {"clip", "time_s", "speed", "loop"});
    object.string("clip", animation.clip);
    object.number("time_s", animation.timeS, Range::closed(-kMaxAnimationTimeS, kMaxAnimationTimeS));
    object.number("speed", animation.speed, Range::closed(-kMaxAnimationSpeed, kMaxAnimationSpeed));
    object.boolean("loop", animation.loop);
}

void readCharacter(JsonContext& context, const json& value, const std::string& pointer, const std::string& sceneFile,
                   const std::vector<std::string>& profiles, Character& character) {
    JsonObject object(context, value, pointer, {"name", "transform", "mesh", "metres_per_unit", "material",
                                                 "materials", "ssao", "animation"});
    object.string("name", character.name);
    readTransform(object, character.transform);
    readMesh(object, sceneFile, character.mesh);
    object.number("metres_per_unit", character.metresPerUnit, Range::above(0.0));
    if (!context.failed()) {
        const double metresPerMeshUnit = double(character.metresPerUnit) * double(character.transform.scale);
        context.check(metresPerMeshUnit >= double(float(kMinMetresPerMeshUnit)) &&
                          metresPerMeshUnit <= double(float(kMaxMetresPerMeshUnit)),
                      object.pointer("metres_per_unit"),
                      "transform.scale x metres_per_unit must be in [" + formatNumberForMessage(kMinMetresPerMeshUnit) +
                          ", " + formatNumberForMessage(kMaxMetresPerMeshUnit) + "] metres per mesh unit, got " +
                          formatSignificantForMessage(metresPerMeshUnit, 3));
    }
    readMaterial(object, sceneFile, profiles, character.material);
    readMaterialOverrides(object, sceneFile, profiles, character);
    readCharacterSsao(object, character.ssao);
    readCharacterAnimation(object, character.animation);
}

void readBackground(JsonObject& root, Background& background) {
    const json* value = root.member("background");
    if (value == nullptr) {
        return;
    }
    JsonObject object(root.context(), *value, root.pointer("background"), {"colour"});
    object.vec3("colour", background.colour, Range::closed(0.0, kMaxLightRadiance));
}

void readEnvironment(JsonObject& root, const std::string& sceneFile, Environment& environment) {
    const json* value = root.member("environment");
    if (value == nullptr) {
        return;
    }
    JsonObject object(root.context(), *value, root.pointer("environment"),
                      {"source", "intensity", "rotation", "background", "occlusion", "specular", "diffuse", "sh_bands",
                       "extract_light", "extract_threshold"});
    std::string source;
    object.string("source", source, false);
    environment.source = isBuiltInEnvironment(source) ? source : resolveScenePath(sceneFile, source);
    object.number("intensity", environment.intensity, Range::closed(0.0, kMaxEnvironmentIntensity));
    object.boolean("background", environment.background);
    choice(object, "occlusion", kEnvironmentOcclusions, environment.occlusion);
    choice(object, "specular", kEnvironmentSpeculars, environment.specular);
    choice(object, "diffuse", kEnvironmentDiffuses, environment.diffuse);
    object.integer("sh_bands", environment.shBands, Range::closed(1, kMaxShBands));
    choice(object, "extract_light", kEnvironmentLightExtractions, environment.extractLight);
    object.number("extract_threshold", environment.extractThreshold,
                  Range::closed(kMinEnvironmentExtractThreshold, kMaxEnvironmentExtractThreshold));
    JsonContext& context = root.context();
    const std::vector<std::string> builtIn(std::begin(kBuiltInEnvironments), std::end(kBuiltInEnvironments));
    if (context.check(object.has("source"), object.pointer("source"),
                      "is required: a built-in environment (" + listForMessage(builtIn, "or") +
                          ") or a lat-long map file")) {
        const json* rotationValue = object.member("rotation");
        if (rotationValue == nullptr) return;
        JsonObject rotation(context, *rotationValue, object.pointer("rotation"), {"axis", "angle_deg", "speed_deg_per_s"});
        rotation.vec3("axis", environment.rotation.axis);
        rotation.number("angle_deg", environment.rotation.angleDeg, Range::closed(-kMaxEnvironmentAngleDeg, kMaxEnvironmentAngleDeg));
        rotation.number("speed_deg_per_s", environment.rotation.speedDegPerS,
                        Range::closed(-kMaxEnvironmentSpeedDegPerS, kMaxEnvironmentSpeedDegPerS));
        if (!context.failed() &&
            context.check(length(environment.rotation.axis) > kParallelTolerance, rotation.pointer("axis"),
                          "must not be the zero vector")) {
            environment.rotation.axis = glm::vec3(normalised(environment.rotation.axis));
        }
    }
}

// Reads the fields a visit lists (SettingsFields.h) from one JSON object.
class FieldReader {
public:
    FieldReader(JsonObject& object, const std::string& sceneFile) : mObject(object), mSceneFile(sceneFile) {}

    void number(const char* key, float& out, const Range& range) { mObject.number(key, out, range); }
    void integer(const char* key, int& out, const Range& range) { mObject.integer(key, out, range); }
    void rule(const char* key, int& out, const IntegerRule& rule) {
        constrainedInteger(mObject, key, out, rule.valid, rule.requirement);
    }
    void boolean(const char* key, bool& out) { mObject.boolean(key, out); }
    void vec3(const char* key, glm::vec3& out, const Range& range) { mObject.vec3(key, out, range); }
    void path(const char* key, std::string& out) {
        std::string value = out;
        mObject.string(key, value);
        out = resolveScenePath(mSceneFile, value);
    }
    template <typename E, size_t N>
    void choice(const char* key, const EnumTable<E, N>& table, E& out) {
        dermis::choice(mObject, key, table, out);
    }
    // A nested object, read when present.
    template <typename G, typename Visit>
    void group(const char* key, G& out, Visit&& visit) {
        const json* value = mObject.member(key);
        if (value == nullptr) {
            return;
        }
        JsonObject object(mObject.context(), *value, mObject.pointer(key), fieldKeys(out, visit));
        FieldReader reader(object, mSceneFile);
        visit(out, reader);
    }

private:
    JsonObject& mObject;
    const std::string& mSceneFile;
};

// With a budget, the table is read now, so a missing or bad file or a table
// tuned for another budget fails the scene load.
void readQualityTable(JsonObject& settingsObject, QualitySettings& quality) {
    JsonContext& context = settingsObject.context();
    const std::string pointer = settingsObject.pointer("quality");
    if (quality.errorBudget <= 0.0f) return;
    if (!context.check(!quality.table.empty(), pointer + "/table",
                       "is required when error_budget > 0 (a quality table made by dermis tune)")) {
        return;
    }
    auto table = loadQualityTable(quality.table);
    if (!table.ok()) {
        context.fail(pointer + "/table", "the quality table " + table.error().where + ": " + table.error().what);
        return;
    }
    if (!context.check(static_cast<float>(table->budget) == quality.errorBudget, pointer + "/error_budget",
                       "is " + formatNumberForMessage(quality.errorBudget) + " but the quality table " + quality.table +
                           " was tuned for an error budget of " + formatNumberForMessage(static_cast<float>(table->budget)) +
                           " (make one with dermis tune SCENE --budget " +
                           formatNumberForMessage(quality.errorBudget) + ")")) {
        return;
    }
    quality.loaded = std::move(*table);
}

void readSettings(JsonObject& root, const std::string& sceneFile, RenderSettings& settings) {
    const json* value = root.member("settings");
    if (value == nullptr) {
        return;
    }
    const auto visit = [](auto& s, auto& v) { visitSettingsFields(s, v); };
    JsonObject object(root.context(), *value, root.pointer("settings"), fieldKeys(settings, visit));
    FieldReader reader(object, sceneFile);
    visit(settings, reader);
    JsonContext& context = root.context();
    if (context.failed()) {
        return;
    }
    const TextureSpaceSettings& ts = settings.ts;
    context.check(ts.minSize <= ts.maxSize, object.pointer("ts") + "/min_size",
                  "must be <= max_size (" + std::to_string(ts.maxSize) + "), got " + std::to_string(ts.minSize));
    readQualityTable(object, settings.quality);
}

}  // namespace

Result<Scene> readSceneDocument(const json& document, const std::string& pathForMessages) {
    Scene scene;
    scene.path = pathForMessages;
    JsonContext context(pathForMessages);
    JsonObject root(context, document, "", {"camera", "lights", "characters", "profiles", "background", "environment",
                                                 "settings"});
    readCamera(root, scene.camera);
    readProfiles(root, scene.profiles);
    std::vector<std::string> profiles = profileNames();
    profiles.emplace_back(kOpaqueProfile);
    for (const DiffusionProfile& profile : scene.profiles) profiles.push_back(profile.name());

    if (const json* lights = root.array("lights", kMaxSceneLights, "lights")) {
        scene.lights.resize(lights->size());
        for (size_t i = 0; i < lights->size() && !context.failed(); ++i) {
            readLight(context, (*lights)[i], root.pointer("lights") + "/" + std::to_string(i), scene.lights[i]);
        }
    }
    if (const json* characters = root.array("characters", kMaxSceneCharacters, "characters")) {
        scene.characters.resize(characters->size());
        for (size_t i = 0; i < characters->size() && !context.failed(); ++i) {
            readCharacter(context, (*characters)[i], root.pointer("characters") + "/" + std::to_string(i),
                          pathForMessages, profiles, scene.characters[i]);
        }
    }
    readBackground(root, scene.background);
    readEnvironment(root, pathForMessages, scene.environment);
    readSettings(root, pathForMessages, scene.settings);

    if (context.failed()) {
        return context.error();
    }
    return scene;
}

Result<Scene> parseScene(const std::string& jsonText, const std::string& pathForMessages) {
    Result<json> document = parseJsonText(jsonText, pathForMessages);
    if (!document) {
        return document.error();
    }
    return readSceneDocument(*document, pathForMessages);
}

Result<Scene> loadScene(const std::string& path) {
    return loadScene(path, {});
}

Result<Scene> loadScene(const std::string& path, const std::vector<std::string>& overrides) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        return makeError(path, "cannot open scene file: it is a directory");
    }
    // A FIFO or a device would block or never end; only files are read.
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec)) {
        return makeError(path, "cannot open scene file: it is not a regular file");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        // Say why: "file not found" for a symlink loop sent users looking for a missing file.
        const std::string reason = std::strerror(errno);
        return makeError(path, "cannot open scene file: " + reason);
    }
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > kMaxJsonTextBytes) {
        return makeError(path, "scene file is " + std::to_string(size) + " bytes; the limit is " +
                                   std::to_string(kMaxJsonTextBytes) + " bytes");
    }
    const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    if (file.bad()) {
        return makeError(path, "cannot read scene file");
    }
    return parseSceneWithOverrides(text, path, overrides);
}

}  // namespace dermis
