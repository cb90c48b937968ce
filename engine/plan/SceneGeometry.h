#pragma once
// The CPU side of a scene that the frame plan needs, kept from load time (no
// GL, no file reading: render/SceneLoading.h loads): each character's mesh
// and object-space bounds, its UV layout (mesh/UvLayout.h), analysed the
// first time a texture-space plan needs it (d'Eon & Luebke 2007 §16.3: the
// stretch sets the texture size and the blur's tap spacing), and the
// environment's light as loaded.
//
//   auto models = loadSceneModels(scene);          // render/SceneLoading.h
//   SceneGeometry geometry(*models);
//   loadEnvironment(scene, geometry);               // render/SceneLoading.h, again when the scene changes
//   FramePlan plan = *planFrame(scene, geometry, request, shadowCache);

#include "core/Result.h"
#include "pose/CharacterPose.h"
#include "mesh/Mesh.h"
#include "mesh/Model.h"
#include "scene/Scene.h"
#include "mesh/UvLayout.h"
#include "plan/EnvironmentPlan.h"
#include "plan/SubmeshScattering.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace dermis {


class SceneGeometry {
public:
    SceneGeometry() = default;
    // Characters that share a model (render/SceneLoading.h) share its mesh here too.
    explicit SceneGeometry(const SceneModels& models);
    explicit SceneGeometry(const std::vector<Model>& models);

    size_t size() const { return mCharacters.size(); }
    const MeshData& mesh(size_t character) const { return mCharacters[character].model->mesh; }
    const Bounds& objectBounds(size_t character) const { return mCharacters[character].objectBounds; }
    // What moves the character's vertices (empty for a static one).
    const Rig& rig(size_t character) const { return *mCharacters[character].rig; }
    // The material of each of its submeshes (mesh/Model.h drawRanges).
    const std::vector<SubmeshMaterial>& submeshMaterials(size_t character) const {
        return mCharacters[character].submeshMaterials;
    }
    // Each level of detail's error against the full mesh, object units, finest
    // first (mesh/Model.h LodLevel); empty: the character has no levels.
    const std::vector<float>& lodErrorsObject(size_t character) const { return mCharacters[character].lodErrorsObject; }
    // The character's UV layout, analysed on first use (CPU; the procedural
    // head takes a fraction of a second) and shared by the characters that
    // share its model at the same scale (`metresPerUnit`, its world size per
    // object unit: analyseUvLayout measures the seams' turn in metres).
    const UvLayout& uvLayout(size_t character, float metresPerUnit);
    // The environment's map, extracted light and SH as loaded
    // (render/SceneLoading.h); null before loading. It stays while the scene has none.
    const std::shared_ptr<const EnvironmentLight>& environmentLight() const { return mEnvironment; }
    void setEnvironmentLight(std::shared_ptr<const EnvironmentLight> light) { mEnvironment = std::move(light); }
    // The loaded light, if it is the one `environment` asks for with
    // `sceneLights` lights in the scene (its source and extraction); null
    // without an environment; an error when it was not loaded (a caller's bug).
    Result<std::shared_ptr<const EnvironmentLight>> environment(const Environment& environment, size_t sceneLights) const;

private:
    std::shared_ptr<const EnvironmentLight> mEnvironment;
    struct Character {
        std::shared_ptr<const Model> model;
        Bounds objectBounds;
        std::shared_ptr<const UvLayout> uvLayout;
        std::shared_ptr<const Rig> rig;
        std::vector<SubmeshMaterial> submeshMaterials;
        std::vector<float> lodErrorsObject;
        float uvLayoutMetresPerUnit = 0.0f;  // the scale uvLayout was analysed at
    };
    std::vector<Character> mCharacters;
};

// A box's world bounds: the bounds of its eight transformed corners.
Bounds transformBounds(const Bounds& bounds, const glm::mat4& worldFromObject);

}  // namespace dermis
