#include "plan/SubmeshScattering.h"

namespace dermis {

Result<std::vector<SubmeshScattering>> submeshScattering(const Scene& scene, size_t index,
                                                         const std::vector<SubmeshMaterial>& materials) {
    const Character& character = scene.characters[index];
    const std::vector<SubmeshMaterial> submeshes = materials.empty() ? std::vector<SubmeshMaterial>{{}} : materials;
    std::vector<SubmeshScattering> out;
    for (const SubmeshMaterial& submesh : submeshes) {
        const Material& material = characterMaterial(character, submesh.name, submesh.index);
        const std::string& profileName = submesh.profile.empty() ? material.profile : submesh.profile;
        SubmeshScattering s;
        s.widthScale = scene.settings.sss.widthScale * material.widthScale;
        if (profileName != kOpaqueProfile) {
            auto profile = findSceneProfile(scene, profileName);
            if (!profile.ok()) return makeError("character '" + character.name + "'", profile.error().what);
            s.profile = *profile;
        }
        out.push_back(s);
    }
    return out;
}

}  // namespace dermis
