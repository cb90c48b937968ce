#pragma once
// The CPU side of a scene's meshes that the frame plan needs, kept from load
// time (no GL): each character's mesh and object-space bounds, and its UV
// layout (mesh/UvLayout.h), analysed the first time a texture-space plan
// needs it (d'Eon & Luebke 2007 §16.3: the stretch sets the texture size and
// the blur's tap spacing).
//
//   auto models = loadSceneModels(scene);      // as the renderer loads them
//   SceneGeometry geometry(*models);
//   FramePlan plan = *planFrame(scene, geometry, request, shadowCache);

#include "core/Result.h"
#include "import/CharacterPose.h"
#include "mesh/Mesh.h"
#include "mesh/Model.h"
#include "scene/Scene.h"
#include "mesh/UvLayout.h"
#include "render/EnvironmentPlan.h"
#include "render/SubmeshScattering.h"

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <vector>

namespace dermis {

// Loads every character's model (import/ModelLoader.h), in scene order. Errors
// name the character; a mesh without triangles is one, and so is an
// animation clip the model does not have (the message lists those it has).
Result<std::vector<Model>> loadSceneModels(const Scene& scene);


class SceneGeometry {
public:
    SceneGeometry() = default;
    explicit SceneGeometry(const std::vector<Model>& models);

    size_t size() const { return mCharacters.size(); }
    const MeshData& mesh(size_t character) const { return mCharacters[character].mesh; }
    const Bounds& objectBounds(size_t character) const { return mCharacters[character].objectBounds; }
    // What moves the character's vertices (empty for a static one).
    const Rig& rig(size_t character) const { return *mCharacters[character].rig; }
    // The material of each of its submeshes (mesh/Model.h drawRanges).
    const std::vector<SubmeshMaterial>& submeshMaterials(size_t character) const {
        return mCharacters[character].submeshMaterials;
    }
    // The character's UV layout, analysed on first use (CPU; the procedural
    // head takes a fraction of a second).
    const UvLayout& uvLayout(size_t character);
    // The environment's map, extracted light and SH, loaded on first use and
    // again when the source changes, split again when the extraction changes
    // (`sceneLights`: how many lights the scene has); null when the scene has
    // none. Errors name the map.
    Result<std::shared_ptr<const EnvironmentLight>> environment(const Environment& environment, size_t sceneLights);

private:
    std::shared_ptr<const EnvironmentLight> mEnvironment;
    struct Character {
        MeshData mesh;
        Bounds objectBounds;
        std::shared_ptr<const UvLayout> uvLayout;
        std::shared_ptr<const Rig> rig;
        std::vector<SubmeshMaterial> submeshMaterials;
    };
    std::vector<Character> mCharacters;
};

// A box's world bounds: the bounds of its eight transformed corners.
Bounds transformBounds(const Bounds& bounds, const glm::mat4& worldFromObject);

}  // namespace dermis
