#pragma once
// Command-line overrides of scene keys: `dermis render SCENE --set sss.taps=13`.
//
// An override is "PATH=VALUE". PATH is dot-separated object keys and array
// indices from the document root ("characters.0.material.roughness"); a PATH
// whose first key is not a root key (camera, lights, characters, background, environment,
// settings) is taken under settings ("sss.taps" == "settings.sss.taps"). VALUE
// is JSON when it parses as JSON (13, false, [0, 0.1, 0.5], "text") and
// otherwise the text itself as a string (sss.blur=control).
//
// Overrides edit the parsed JSON document before the strict reading, so they
// are validated exactly like the file (see parseSceneWithOverrides).

#include "core/Result.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis {

struct SceneOverride {
    std::string text;               // as given: "sss.taps=13"
    std::vector<std::string> path;  // from the root: {"settings", "sss", "taps"}
    nlohmann::json value;

    std::string where() const;    // "--set sss.taps=13", the Error::where of its errors
    std::string pointer() const;  // "/settings/sss/taps"
};

// Errors: Error{"--set x", "expected PATH=VALUE"}, or an empty key in PATH.
Result<SceneOverride> parseSceneOverride(const std::string& text);

// Sets the value at the override's path, creating missing objects on the way.
// An array element must already exist. Errors name the override.
Status applySceneOverride(nlohmann::json& document, const SceneOverride& change);

}  // namespace dermis
