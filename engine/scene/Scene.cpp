#include "scene/Scene.h"

#include <glm/gtc/matrix_transform.hpp>

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

}  // namespace dermis
