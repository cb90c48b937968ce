#include "import/MaterialScattering.h"

#include <algorithm>
#include <cctype>

namespace dermis {

std::vector<std::string> materialNameWords(const std::string& name) {
    std::vector<std::string> words;
    std::string word;
    auto flush = [&] {
        if (!word.empty()) words.push_back(word);
        word.clear();
    };
    for (size_t i = 0; i < name.size(); ++i) {
        const auto c = static_cast<unsigned char>(name[i]);
        if (!std::isalpha(c)) {
            flush();
            continue;
        }
        const bool lowerToUpper = i > 0 && std::isupper(c) && std::islower(static_cast<unsigned char>(name[i - 1]));
        if (lowerToUpper) flush();
        word += static_cast<char>(std::tolower(c));
    }
    flush();
    return words;
}

namespace {

// The word of the name that marks it as not skin, or "".
std::string notSkinWord(const std::string& name) {
    for (const std::string& word : materialNameWords(name)) {
        if (std::find(std::begin(kNotSkinWords), std::end(kNotSkinWords), word) != std::end(kNotSkinWords)) return word;
    }
    return "";
}

void makeOpaque(ModelMaterial& material, std::string reason) {
    material.profile = std::string(kOpaqueProfile);
    material.scatter = 0.0f;
    material.scatterReason = std::move(reason);
}

}  // namespace

void decideScattering(const Character& character, size_t index, ModelMaterial& material) {
    material.thicknessMm = material.thicknessFactor * character.metresPerUnit * character.transform.scale * 1000.0f;
    const Material* entry = sceneMaterialEntry(character, material.name, index);
    if (entry && entry->scatteringGiven) {
        material.profile = entry->profile;
        material.scatter = entry->scatter;
        material.scatterReason = kSceneScatterReason;
    } else if (material.diffuseTransmission >= 0.0f) {
        material.profile = material.diffuseTransmission > 0.0f ? character.material.profile : std::string(kOpaqueProfile);
        material.scatter = material.diffuseTransmission;
        material.scatterMap = std::move(material.diffuseTransmissionMap);  // read nowhere else; its sampler is scatterWrap
        material.scatterReason = "KHR_materials_diffuse_transmission";
    } else if (material.alphaMode != "OPAQUE") {
        makeOpaque(material, "alphaMode " + material.alphaMode);
    } else if (material.transmission > 0.0f) {
        makeOpaque(material, "KHR_materials_transmission (glass)");
    } else if (const std::string word = notSkinWord(material.name); !word.empty()) {
        makeOpaque(material, "its name says \"" + word + "\"");
    } else {
        material.profile = character.material.profile;
        material.scatter = character.material.scatter;
        material.scatterReason = kCharacterScatterReason;
    }
    if (material.profile == kOpaqueProfile) material.scatter = 0.0f;
}

}  // namespace dermis
