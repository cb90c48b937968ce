#pragma once
// Turns a character's mesh source and material into a Model: the procedural
// generator or the glTF loader, then any maps the material names explicitly
// (which replace the model's own).

#include "core/Result.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

namespace dermis {

Result<Model> loadCharacterModel(const Character& character);

// Every name in the character's `materials` is one of the model's materials;
// the error names the scene key and lists the file's material names.
Status checkMaterialNames(const Scene& scene, size_t characterIndex, const Model& model);

}  // namespace dermis
