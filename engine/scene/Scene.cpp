#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/component_wise.hpp>

#include <cstdio>

namespace dermis {

glm::mat4 Transform::worldFromObject(float metresPerUnit) const {
    const glm::mat4 identity(1.0f);
    const glm::mat4 t = glm::translate(identity, translationM);
    const glm::mat4 rx = glm::rotate(identity, glm::radians(rotationDeg.x), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::mat4 ry = glm::rotate(identity, glm::radians(rotationDeg.y), glm::vec3(0.0f, 1.0f, 0.0f));
    const glm::mat4 rz = glm::rotate(identity, glm::radians(rotationDeg.z), glm::vec3(0.0f, 0.0f, 1.0f));
    const glm::mat4 s = glm::scale(identity, glm::vec3(scale * metresPerUnit));
    return t * rz * ry * rx * s;
}

bool isBuiltInEnvironment(const std::string& source) {
    for (std::string_view name : kBuiltInEnvironments)
        if (source == name) return true;
    return false;
}

glm::mat3 Environment::worldFromMap(float timeS) const {
    const float angleDeg = rotation.angleDeg + rotation.speedDegPerS * timeS;
    return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(angleDeg), rotation.axis));
}

const Material& characterMaterial(const Character& character, const std::string& gltfMaterialName) {
    const auto found = character.materials.find(gltfMaterialName);
    return found == character.materials.end() ? character.material : found->second;
}

const Material* sceneMaterialEntry(const Character& character, const std::string& gltfMaterialName, size_t index) {
    auto found = character.materials.find(gltfMaterialName);
    if (found == character.materials.end()) found = character.materials.find(materialIndexKey(index));
    return found == character.materials.end() ? nullptr : &found->second;
}

const Material& characterMaterial(const Character& character, const std::string& gltfMaterialName, size_t index) {
    const Material* entry = sceneMaterialEntry(character, gltfMaterialName, index);
    return entry ? *entry : character.material;
}

std::string materialIndexKey(size_t index) { return "#" + std::to_string(index); }

Result<const DiffusionProfile*> findSceneProfile(const Scene& scene, const std::string& name) {
    for (const DiffusionProfile& profile : scene.profiles)
        if (profile.name() == name) return &profile;
    auto builtin = findProfile(name);
    if (builtin.ok()) return builtin;
    std::string known;
    for (const std::string& n : profileNames()) known += (known.empty() ? "" : ", ") + n;
    for (const DiffusionProfile& profile : scene.profiles) known += ", " + profile.name();
    return makeError("", "unknown diffusion profile \"" + name + "\" (known: " + known + ")");
}

Error atSceneKey(const Scene& scene, const std::string& pointer, const Error& cause) {
    const std::string where = scene.path.empty() ? pointer : scene.path + ": " + pointer;
    return Error{where, cause.message()};
}

std::string unlitSceneReason(const Scene& scene) {
    bool lit = false;
    for (const Light& light : scene.lights) lit = lit || (light.intensity > 0.0f && glm::compMax(light.colour) > 0.0f);
    if (lit || (scene.environment.enabled() && scene.environment.intensity > 0.0f)) return "";
    const std::string what = scene.lights.empty() ? "no light" : "no light of non-zero intensity and colour";
    const std::string environment = scene.environment.enabled() ? "an environment of intensity 0" : "no environment";
    const float ambient = glm::compMax(scene.settings.ambient);
    char tail[96];
    std::snprintf(tail, sizeof tail, ambient > 0.0f ? "; only the ambient term (%.3g) lights it" : "; nothing lights it", ambient);
    return what + " and " + environment + tail;
}

}  // namespace dermis
