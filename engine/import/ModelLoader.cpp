#include "import/ModelLoader.h"

#include "core/Log.h"
#include "import/GltfLoader.h"
#include "import/MaterialScattering.h"
#include "procedural/Procedural.h"

#include <map>

namespace dermis {
namespace {

// Loads each image file once, however many materials name it: the first
// material that names it receives the decoded image, later ones a copy of
// that material's. No cache holds a further copy, so the peak is the images
// the model keeps (a map can be 1 GiB decoded, core/Image.h kMaxImageTexels).
class MapFiles {
public:
    Status load(const std::string& path, ColourSpace colourSpace, Image& out) {
        if (path.empty()) return success();
        auto first = mFirstHolder.find({path, colourSpace});
        // The first holder may have dropped it since (use_normal_map false).
        if (first != mFirstHolder.end() && !first->second->empty()) {
            out = *first->second;
            return success();
        }
        auto image = loadImage(path, colourSpace);
        if (!image.ok()) return image.error();
        out = std::move(*image);
        mFirstHolder[{path, colourSpace}] = &out;
        return success();
    }

private:
    // Each image lives in a material of the model being loaded, whose
    // material list does not change size while the maps are loaded.
    std::map<std::pair<std::string, ColourSpace>, const Image*> mFirstHolder;
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
    for (size_t index = 0; index < model->materials.size(); ++index) {
        ModelMaterial& target = model->materials[index];
        const Material& material = characterMaterial(character, target.name, index);
        decideScattering(character, index, target);
        const bool sceneDecides = target.scatterReason == kSceneScatterReason ||
                                  target.scatterReason == kCharacterScatterReason;
        if (sceneDecides) {
            const Material* entry = sceneMaterialEntry(character, target.name, index);
            const std::string& scatterMap = entry && entry->scatteringGiven ? entry->scatterMap : character.material.scatterMap;
            if (Status status = files.load(scatterMap, ColourSpace::Linear, target.scatterMap); !status) return status.error();
        }
        if (target.scatterReason != kCharacterScatterReason && !target.scatterReason.empty())
            log::info("character '" + character.name + "': material " + std::to_string(index) + " '" + target.name +
                      "' " + (target.profile == kOpaqueProfile ? "does not scatter" : "scatters " + target.profile) +
                      " (" + target.scatterReason + ")");
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
        for (size_t m = 0; m < model.materials.size(); ++m) found = found || entry.first == materialIndexKey(m);
        for (const ModelMaterial& material : model.materials) {
            found = found || material.name == entry.first;
            if (!material.name.empty()) names += (names.empty() ? "'" : ", '") + material.name + "'";
        }
        if (found) continue;
        const std::string source = character.mesh.gltfPath.empty() ? "its mesh" : character.mesh.gltfPath;
        return makeError(scene.path, "/characters/" + std::to_string(index) + "/materials/" + entry.first + ": '" +
                                         entry.first + "' is not a material of " + source + " (its materials: " +
                                         (names.empty() ? "none named" : names) + "; or #0 to #" +
                                         std::to_string(model.materials.size() - 1) + " by index)");
    }
    return success();
}

}  // namespace dermis
