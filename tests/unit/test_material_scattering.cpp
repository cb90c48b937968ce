// Which materials scatter (import/MaterialScattering.h, docs/materials.md
// "Skin only where there is skin"): the rules in order, each checked on a
// material that a later rule would decide otherwise, so that dropping or
// reordering a rule fails here.
#include "TestSupport.h"

#include "import/MaterialScattering.h"
#include "import/ModelLoader.h"
#include "scene/SceneLoader.h"

#include <gtest/gtest.h>

using namespace dermis;

namespace {

Character skinCharacter() {
    Character character;
    character.name = "avatar";
    character.material.profile = "skin";
    return character;
}

ModelMaterial named(const std::string& name) {
    ModelMaterial material;
    material.name = name;
    return material;
}

ModelMaterial decided(const Character& character, ModelMaterial material, size_t index = 0) {
    decideScattering(character, index, material);
    return material;
}

}  // namespace

TEST(MaterialScattering, NameWordsSplitAtCaseAndPunctuation) {
    EXPECT_EQ(materialNameWords("Wolf3D_EyeIris"), (std::vector<std::string>{"wolf", "d", "eye", "iris"}));
    EXPECT_EQ(materialNameWords("N00_000_Hair_00_HAIR"), (std::vector<std::string>{"n", "hair", "hair"}));
    EXPECT_EQ(materialNameWords("Headwear"), (std::vector<std::string>{"headwear"}));
    EXPECT_TRUE(materialNameWords("").empty());
}

TEST(MaterialScattering, AvatarNamesKeepHairEyesTeethClothAndGlassesOpaque) {
    const Character character = skinCharacter();
    // Ready Player Me and VRoid material names.
    for (const char* name : {"Wolf3D_Hair", "Wolf3D_Eye", "Wolf3D_Teeth", "Wolf3D_Outfit_Top", "Wolf3D_Glasses",
                             "Wolf3D_Beard", "N00_000_00_EyeIris_00_EYE", "N00_001_01_Bottoms_01_CLOTH", "Eyelashes"}) {
        const ModelMaterial m = decided(character, named(name));
        EXPECT_EQ(m.profile, "none") << name;
        EXPECT_EQ(m.scatter, 0.0f) << name;
        EXPECT_NE(m.scatterReason.find("its name says"), std::string::npos) << name << ": " << m.scatterReason;
    }
    // Words that only contain a non-skin word are skin: eyelids, the face, the body.
    for (const char* name : {"Wolf3D_Skin", "Wolf3D_Body", "Eyelid", "N00_000_00_FaceMouth_00_FACE", "", "Material.001"}) {
        const ModelMaterial m = decided(character, named(name));
        EXPECT_EQ(m.profile, "skin") << name;
        EXPECT_EQ(m.scatter, 1.0f) << name;
    }
}

TEST(MaterialScattering, FileSignalsComeBeforeTheName) {
    const Character character = skinCharacter();
    ModelMaterial card = named("Skin_card");
    card.alphaMode = "MASK";
    EXPECT_EQ(decided(character, card).profile, "none");
    ModelMaterial glass = named("Visor");
    glass.transmission = 0.9f;
    EXPECT_EQ(decided(character, glass).profile, "none");
    // Diffuse transmission decides before alpha and the name: its factor is s.
    ModelMaterial hair = named("Hair");
    hair.alphaMode = "BLEND";
    hair.diffuseTransmission = 0.25f;
    hair.diffuseTransmissionMap.width = 1;
    hair.diffuseTransmissionMap.height = 1;
    hair.diffuseTransmissionMap.texels = {glm::vec4(0.5f)};
    const ModelMaterial translucent = decided(character, hair);
    EXPECT_EQ(translucent.profile, "skin");
    EXPECT_FLOAT_EQ(translucent.scatter, 0.25f);
    ASSERT_FALSE(translucent.scatterMap.empty());
    EXPECT_FLOAT_EQ(translucent.scatterMap.texels[0].r, 0.5f);
    ModelMaterial none = named("Skin");
    none.diffuseTransmission = 0.0f;
    EXPECT_EQ(decided(character, none).profile, "none");
}

TEST(MaterialScattering, SceneEntryDecidesOnlyWhenItGivesScattering) {
    Character character = skinCharacter();
    Material hairAsSkin = character.material;
    hairAsSkin.scatteringGiven = true;
    hairAsSkin.scatter = 0.3f;
    character.materials["Wolf3D_Hair"] = hairAsSkin;
    Material roughOnly = character.material;
    roughOnly.roughness = 0.7f;
    character.materials["Wolf3D_Teeth"] = roughOnly;
    Material byIndex = character.material;
    byIndex.scatteringGiven = true;
    byIndex.profile = "none";
    character.materials["#2"] = byIndex;
    const ModelMaterial hair = decided(character, named("Wolf3D_Hair"), 0);
    EXPECT_EQ(hair.profile, "skin");
    EXPECT_FLOAT_EQ(hair.scatter, 0.3f);
    EXPECT_EQ(decided(character, named("Wolf3D_Teeth"), 1).profile, "none");  // the name still decides
    EXPECT_EQ(decided(character, named("Wolf3D_Skin"), 2).profile, "none");   // "#2"
    EXPECT_EQ(decided(character, named("Wolf3D_Skin"), 3).profile, "skin");
}

TEST(MaterialScattering, VolumeThicknessIsInMillimetresOfTheScene) {
    Character character = skinCharacter();
    character.metresPerUnit = 0.01f;  // centimetres
    character.transform.scale = 2.0f;
    ModelMaterial ear = named("Skin");
    ear.thicknessFactor = 0.5f;  // 0.5 cm in the file's units, doubled by the scale: 10 mm
    EXPECT_FLOAT_EQ(decided(character, ear).thicknessMm, 10.0f);
}

TEST(MaterialScattering, SceneKeysAreReadAndChecked) {
    auto scene = parseScene(R"({"characters": [{"name": "a", "mesh": {"procedural": "plane"},
        "material": {"scatter": 0.5}, "materials": {"#0": {"roughness": 0.5}, "Hair": {"scatter": 0}}}]})", "s.json");
    ASSERT_TRUE(scene) << scene.error().message();
    const Character& character = scene->characters[0];
    EXPECT_FLOAT_EQ(character.material.scatter, 0.5f);
    EXPECT_FALSE(character.materials.at("#0").scatteringGiven);
    EXPECT_TRUE(character.materials.at("Hair").scatteringGiven);
    auto bad = parseScene(R"({"characters": [{"name": "a", "mesh": {"procedural": "plane"},
        "material": {"scatter": 1.5}}]})", "s.json");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message().find("/characters/0/material/scatter: must be in [0, 1], got 1.5"), std::string::npos)
        << bad.error().message();
}

TEST(MaterialScattering, IndexKeysBeyondTheModelAreRefused) {
    auto scene = parseScene(R"({"characters": [{"name": "a", "mesh": {"procedural": "plane"},
        "materials": {"#1": {"profile": "none"}}}]})", "s.json");
    ASSERT_TRUE(scene) << scene.error().message();
    auto model = loadCharacterModel(scene->characters[0]);
    ASSERT_TRUE(model) << model.error().message();
    const Status names = checkMaterialNames(*scene, 0, *model);
    ASSERT_FALSE(names);
    EXPECT_NE(names.error().message().find("'#1' is not a material of its mesh"), std::string::npos)
        << names.error().message();
    EXPECT_NE(names.error().message().find("#0 to #0 by index"), std::string::npos) << names.error().message();
}
