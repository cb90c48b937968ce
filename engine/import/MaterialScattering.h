#pragma once
// Whether, and how much, each material of a character scatters light
// beneath its surface (docs/materials.md, "Skin only where there is skin").
// Hair, eyes, teeth, clothes and glasses must stay sharp and not glow, and a
// file rarely says which of its materials are skin, so the first of these
// rules that applies decides:
//   1. the scene's entry for the material (`materials` by name or "#index")
//      gives `profile`, `scatter` or `scatter_map`: its values;
//   2. the file gives KHR_materials_diffuse_transmission: s = its factor x
//      its texture's A, with the character's profile (factor 0: opaque);
//   3. alphaMode MASK or BLEND (hair cards, lashes, lenses): opaque;
//   4. KHR_materials_transmission above 0 (glass): opaque;
//   5. a word of the material's name says it is not skin (kNotSkinWords:
//      "Wolf3D_Hair", "EyeIris", "Outfit_Top"): opaque;
//   6. otherwise the character's `material` (skin unless the scene says).
// KHR_materials_volume's thickness, when the file gives one, replaces the
// shadow maps' estimate in the transmittance.

#include "mesh/Model.h"
#include "scene/Scene.h"

#include <string>
#include <string_view>

namespace dermis {

// Whole words of a material name (split at non-letters and lower-to-upper
// case changes, compared lower case) that mark a surface that is not skin.
inline constexpr std::string_view kNotSkinWords[] = {
    "hair",  "hairs",   "beard",  "moustache", "mustache", "brow",     "brows",   "eyebrow",   "eyebrows", "lash",
    "lashes", "eyelash", "eyelashes", "eye",   "eyes",     "iris",     "pupil",   "cornea",    "sclera",   "teeth",
    "tooth", "cloth",   "clothes", "clothing", "outfit",   "shirt",    "tshirt",  "pants",     "trousers", "dress",
    "skirt", "jacket",  "coat",   "shoe",      "shoes",    "boot",     "boots",   "footwear",  "headwear", "hat",
    "cap",   "glass",   "glasses", "lens",     "lenses",   "spectacles", "jewelry", "jewellery", "earring", "necklace"};

// ModelMaterial::scatterReason of rules 1 and 6: the scene decides, and its scatter map applies.
inline constexpr const char* kSceneScatterReason = "the scene's materials entry";
inline constexpr const char* kCharacterScatterReason = "the character's material";

// The words of a material name, lower case ("Wolf3D_EyeIris" -> wolf, d, eye, iris).
std::vector<std::string> materialNameWords(const std::string& name);

// Fills material.profile, scatter, thicknessMm and scatterReason from the
// rules above (material `index` of the character's model). The scene's
// scatter map is the caller's to load (import/ModelLoader.cpp); the file's
// diffuse-transmission texture becomes the scatter map here.
void decideScattering(const Character& character, size_t index, ModelMaterial& material);

}  // namespace dermis
