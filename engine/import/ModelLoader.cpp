#include "import/ModelLoader.h"

#include "import/GltfLoader.h"
#include "procedural/Procedural.h"

#include <map>

namespace dermis {
namespace {

// Loads each image file once, however many materials name it.
class MapFiles {
public:
    Status load(const std::string& path, ColourSpace colourSpace, Image& out) {
        if (path.empty()) return success();
        auto cached = mImages.find({path, colourSpace});
        if (cached == mImages.end()) {
            auto image = loadImage(path, colourSpace);
            if (!image.ok()) return image.error();
            cached = mImages.emplace(std::make_pair(path, colourSpace), std::move(*image)).first;
        }
        out = cached->second;
        return success();
    }

private:
    std::map<std::pair<std::string, ColourSpace>, Image> mImages;
};

}  // namespace

Result<Model> loadCharacterModel(const Character& character) {
    auto model = character.mesh.gltfPath.empty() ? makeProceduralModel(character.mesh.procedural)
                                                 : loadGltf(character.mesh.gltfPath);
    if (!model.ok()) {
        Error error = model.error();
        if (error.where.empty()) error.where = "character '" + character.name + "'";
        return error;
    }
    MapFiles files;
    for (ModelMaterial& target : model->materials) {
        const Material& material = characterMaterial(character, target.name);
        if (!character.mesh.procedural.empty() && !material.procedural) {
            target.albedoMap = Image{};
            target.normalMap = Image{};
        }
        for (Status status : {files.load(material.albedoMap, ColourSpace::Srgb, target.albedoMap),
                              files.load(material.normalMap, ColourSpace::Linear, target.normalMap),
                              files.load(material.roughnessMap, ColourSpace::Linear, target.roughnessMap),
                              files.load(material.specularMap, ColourSpace::Linear, target.specularMap)})
            if (!status) return status.error();
        if (!material.useNormalMap) target.normalMap = Image{};
    }
    return model;
}

Status checkMaterialNames(const Scene& scene, size_t index, const Model& model) {
    const Character& character = scene.characters[index];
    for (const auto& entry : character.materials) {
        bool found = false;
        std::string names;
        for (const ModelMaterial& material : model.materials) {
            found = found || material.name == entry.first;
            if (!material.name.empty()) names += (names.empty() ? "'" : ", '") + material.name + "'";
        }
        if (found) continue;
        const std::string source = character.mesh.gltfPath.empty() ? "its mesh" : character.mesh.gltfPath;
        return makeError(scene.path, "/characters/" + std::to_string(index) + "/materials/" + entry.first + ": '" +
                                         entry.first + "' is not a material of " + source + " (its materials: " +
                                         (names.empty() ? "none named" : names) + ")");
    }
    return success();
}

}  // namespace dermis
