#include "import/GltfTextureTransform.h"

#include "core/Log.h"

#include <cmath>
#include <vector>

namespace dermis {
namespace {

constexpr const char* kExtension = "KHR_texture_transform";

Result<glm::vec2> readPair(const tinygltf::Value& object, const char* key, glm::vec2 fallback, const std::string& where,
                           const std::string& path) {
    if (!object.Has(key)) return fallback;
    const tinygltf::Value& value = object.Get(key);
    if (!value.IsArray() || value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
        return makeError(path, where + ": " + kExtension + " " + key + " must be an array of two numbers");
    const glm::vec2 pair(float(value.Get(0).GetNumberAsDouble()), float(value.Get(1).GetNumberAsDouble()));
    if (!std::isfinite(pair.x) || !std::isfinite(pair.y))
        return makeError(path, where + ": " + kExtension + " " + key + " is not finite");
    return pair;
}

bool sameTransform(const UvTransform& a, const UvTransform& b) { return a.uvFromFile == b.uvFromFile; }

}  // namespace

Result<UvTransform> readTextureTransform(const tinygltf::ExtensionMap& extensions, const std::string& where,
                                         const std::string& path) {
    UvTransform transform;
    const auto it = extensions.find(kExtension);
    if (it == extensions.end()) return transform;
    const tinygltf::Value& object = it->second;
    if (!object.IsObject()) return makeError(path, where + ": " + kExtension + " must be an object");
    Result<glm::vec2> offset = readPair(object, "offset", glm::vec2(0.0f), where, path);
    if (!offset) return offset.error();
    Result<glm::vec2> scale = readPair(object, "scale", glm::vec2(1.0f), where, path);
    if (!scale) return scale.error();
    float rotation = 0.0f;
    if (object.Has("rotation")) {
        const tinygltf::Value& value = object.Get("rotation");
        if (!value.IsNumber() || !std::isfinite(value.GetNumberAsDouble()))
            return makeError(path, where + ": " + kExtension + " rotation must be a number (radians)");
        rotation = float(value.GetNumberAsDouble());
    }
    if (object.Has("texCoord") && object.Get("texCoord").IsNumber() && object.Get("texCoord").GetNumberAsDouble() != 0.0)
        log::warn(path + ": " + where + ": " + kExtension + " selects another texCoord; only TEXCOORD_0 is loaded");
    // Column-major: translation x rotation x scale. The rotation turns UVs counter-clockwise
    // as the image is seen (v down): the extension's worked example (offset [0, 1], rotation
    // pi/2, scale 0.5 reads the lower-left quadrant turned) needs these columns; the GLSL
    // printed above it, read as GLSL's column-major constructor, is their transpose.
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 translationM(1, 0, 0, 0, 1, 0, offset->x, offset->y, 1);
    const glm::mat3 rotationM(c, -s, 0, s, c, 0, 0, 0, 1);
    const glm::mat3 scaleM(scale->x, 0, 0, 0, scale->y, 0, 0, 0, 1);
    transform.uvFromFile = translationM * rotationM * scaleM;
    transform.identity = transform.uvFromFile == glm::mat3(1.0f);
    return transform;
}

Result<UvTransform> materialUvTransform(const tinygltf::Model& gltf, int material, const std::string& path) {
    if (material < 0 || static_cast<size_t>(material) >= gltf.materials.size()) return UvTransform{};
    const tinygltf::Material& m = gltf.materials[static_cast<size_t>(material)];
    struct Reference {
        const char* role;
        int texture;
        const tinygltf::ExtensionMap* extensions;
    };
    const Reference references[] = {
        {"baseColorTexture", m.pbrMetallicRoughness.baseColorTexture.index, &m.pbrMetallicRoughness.baseColorTexture.extensions},
        {"normalTexture", m.normalTexture.index, &m.normalTexture.extensions},
        {"metallicRoughnessTexture", m.pbrMetallicRoughness.metallicRoughnessTexture.index,
         &m.pbrMetallicRoughness.metallicRoughnessTexture.extensions},
        {"occlusionTexture", m.occlusionTexture.index, &m.occlusionTexture.extensions},
        {"emissiveTexture", m.emissiveTexture.index, &m.emissiveTexture.extensions},
    };
    const std::string materialName = "material " + std::to_string(material) + (m.name.empty() ? "" : " '" + m.name + "'");
    UvTransform chosen;
    const char* chosenRole = nullptr;
    std::vector<std::string> disagreeing;
    for (const Reference& reference : references) {
        if (reference.texture < 0) continue;
        Result<UvTransform> transform = readTextureTransform(*reference.extensions, materialName + " " + reference.role, path);
        if (!transform) return transform.error();
        if (!chosenRole) {
            chosen = *transform;
            chosenRole = reference.role;
        } else if (!sameTransform(chosen, *transform)) {
            disagreeing.push_back(reference.role);
        }
    }
    if (!disagreeing.empty()) {
        std::string names;
        for (const std::string& role : disagreeing) names += (names.empty() ? "" : ", ") + role;
        log::warn(path + ": " + materialName + ": " + names + " use another " + kExtension + " than " + chosenRole +
                  "; Dermis draws all maps of a primitive with one set of UVs, " + chosenRole + "'s");
    }
    return chosen;
}

}  // namespace dermis
