#pragma once
// Reads a scene JSON file (format: content/scenes/README.md). Strict: an
// unknown key, a wrong type or an unknown enum value is an error that names
// the file and the JSON path, e.g.
//   "content/scenes/x.json: /lights/1/type: unknown light type \"laser\"
//    (expected directional, spot or point)".

#include "core/Result.h"
#include "scene/Scene.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace dermis {

Result<Scene> loadScene(const std::string& path);
Result<Scene> parseScene(const std::string& jsonText, const std::string& pathForMessages);

// With command-line overrides ("settings.sss.taps=13", "sss.taps=13"; syntax in
// SceneOverrides.h), applied to the JSON document before it is read, so they
// are checked as strictly as the file. An error caused by an override names
// it: Error{"--set sss.taps=4", "/settings/sss/taps: must be an odd number ..."}.
Result<Scene> loadScene(const std::string& path, const std::vector<std::string>& overrides);
Result<Scene> parseSceneWithOverrides(const std::string& jsonText, const std::string& pathForMessages,
                                      const std::vector<std::string>& overrides);

// The reading half of parseScene, for a document already parsed (and edited).
Result<Scene> readSceneDocument(const nlohmann::json& document, const std::string& pathForMessages);

// Serialises every field, so that parseScene(sceneToJson(s)) == s (used by the
// viewer to write its settings back).
std::string sceneToJson(const Scene& scene);

}  // namespace dermis
