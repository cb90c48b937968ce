#pragma once
// How each submesh of a character scatters light: the diffusion profile and
// width scale of the scene material its glTF material name resolves to
// (Scene.h characterMaterial). Both SSS planners (plan/SssPlan.h,
// plan/TsPlan.h) group submeshes by it.

#include "core/Result.h"
#include "scene/Scene.h"
#include "sss/DiffusionProfile.h"

#include <string>
#include <vector>

namespace dermis {

// A submesh's material as the planners need it: the glTF material's name and
// index (a scene names it by either) and the profile its load decided
// (ModelMaterial::profile, import/MaterialScattering.h; empty: the scene
// material's own).
struct SubmeshMaterial {
    std::string name;
    size_t index = 0;
    std::string profile;
};

struct SubmeshScattering {
    const DiffusionProfile* profile = nullptr;  // null: opaque ("none")
    float widthScale = 1.0f;                    // settings.sss.widthScale x the material's width_scale

    bool sameAs(const SubmeshScattering& other) const {
        return profile == other.profile && widthScale == other.widthScale;
    }
};

// One entry per submesh of `materials` (empty: one submesh with the
// character's material). Errors name the character and the unknown profile.
Result<std::vector<SubmeshScattering>> submeshScattering(const Scene& scene, size_t character,
                                                         const std::vector<SubmeshMaterial>& materials);

}  // namespace dermis
