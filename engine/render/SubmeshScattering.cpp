#include "render/SubmeshScattering.h"

namespace dermis {

Result<std::vector<SubmeshScattering>> submeshScattering(const Scene& scene, size_t index,
                                                         const std::vector<std::string>& materialNames) {
    const Character& character = scene.characters[index];
    const std::vector<std::string> names = materialNames.empty() ? std::vector<std::string>{""} : materialNames;
    std::vector<SubmeshScattering> out;
    for (const std::string& name : names) {
        const Material& material = characterMaterial(character, name);
        SubmeshScattering s;
        s.widthScale = scene.settings.sss.widthScale * material.widthScale;
        if (material.profile != kOpaqueProfile) {
            auto profile = findSceneProfile(scene, material.profile);
            if (!profile.ok()) return makeError("character '" + character.name + "'", profile.error().what);
            s.profile = *profile;
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace dermis
