#pragma once
// Reads a scene JSON file (format: content/scenes/README.md). Strict: an
// unknown key, a wrong type or an unknown enum value is an error that names
// the file and the JSON path, e.g.
//   "content/scenes/x.json: /lights/1/type: unknown light type \"laser\"
//    (expected directional, spot or point)".

#include "core/Result.h"
#include "scene/Scene.h"

#include <string>

namespace dermis {

Result<Scene> loadScene(const std::string& path);
Result<Scene> parseScene(const std::string& jsonText, const std::string& pathForMessages);

// Serialises every field, so that loadScene(saveScene(s)) == s (used by the
// viewer to write its settings back).
std::string sceneToJson(const Scene& scene);

}  // namespace dermis
