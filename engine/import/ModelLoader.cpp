#include "import/ModelLoader.h"

#include "import/GltfLoader.h"
#include "procedural/Procedural.h"

namespace dermis {

Result<Model> loadCharacterModel(const Character& character) {
    auto model = character.mesh.gltfPath.empty() ? makeProceduralModel(character.mesh.procedural)
                                                 : loadGltf(character.mesh.gltfPath);
    if (!model.ok()) {
        Error error = model.error();
        if (error.where.empty()) error.where = "character '" + character.name + "'";
        return error;
    }
    const Material& material = character.material;
    if (!character.mesh.procedural.empty() && !material.procedural) {
        model->albedoMap = Image{};
        model->normalMap = Image{};
    }
    if (!material.albedoMap.empty()) {
        auto image = loadImage(material.albedoMap, ColourSpace::Srgb);
        if (!image.ok()) return image.error();
        model->albedoMap = std::move(*image);
    }
    if (!material.normalMap.empty()) {
        auto image = loadImage(material.normalMap, ColourSpace::Linear);
        if (!image.ok()) return image.error();
        model->normalMap = std::move(*image);
    }
    return model;
}

}  // namespace dermis
