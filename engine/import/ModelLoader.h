#pragma once
// Turns a character's mesh source and material into a Model: the procedural
// generator or the glTF loader, then any maps the material names explicitly
// (which replace the model's own).

#include "core/Result.h"
#include "mesh/Model.h"
#include "scene/Scene.h"

namespace dermis {

Result<Model> loadCharacterModel(const Character& character);

}  // namespace dermis
