#pragma once
// What a frame plan reads from files, loaded before planning: the
// characters' models and the environment's map. The plan layer (engine/plan)
// does no file reading; the Renderer calls these first.

#include "core/Result.h"
#include "mesh/Model.h"
#include "plan/EnvironmentPlan.h"
#include "plan/SceneGeometry.h"
#include "scene/Scene.h"

#include <memory>
#include <vector>

namespace dermis {

// Loads every character's model (import/ModelLoader.h), in scene order.
// Characters whose models would load the same (the same mesh source,
// material and materials) share one: a crowd of one head loads it once, and
// GpuScene uploads its maps once. Errors name the character; a mesh without
// triangles is one, and so is an animation clip the model does not have (the
// message lists those it has). With settings.lod.max_error_px above 0 each
// distinct mesh gets its levels of detail (mesh/MeshLod.h) and their normal
// maps (mesh/LodNormalMaps.h); a scene that turns levels on after loading
// draws full meshes.
Result<SceneModels> loadSharedSceneModels(const Scene& scene);
// The same, each character with a copy of its own (for code that changes them).
Result<std::vector<Model>> loadSceneModels(const Scene& scene);

// The environment's map (import/EnvironmentSource.h), split by the scene's extraction settings.
Result<std::shared_ptr<const EnvironmentLight>> loadEnvironmentLight(const Environment& environment, size_t sceneLights);

// Gives `geometry` the environment light the scene asks for now: loaded when
// the source changes, split again (no reading) when only the extraction
// changes, nothing when it is current or the scene has no environment.
// Errors name the map.
Status loadEnvironment(const Scene& scene, SceneGeometry& geometry);

}  // namespace dermis
