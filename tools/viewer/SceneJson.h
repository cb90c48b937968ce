#pragma once
// Scenes compared and edited key by key through their JSON form (sceneToJson),
// which names every knob the same way the scene files and --set do. The
// camera is left out: the A and B sides always share the viewer's camera.

#include "core/Result.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace dermis::viewer {

struct SceneDifference {
    std::string key;  // "settings.sss.blur", as --set writes it
    std::string a;    // the values as JSON text; empty where a side lacks the key
    std::string b;
};

std::vector<SceneDifference> diffScenes(const Scene& a, const Scene& b);

// Applies to `other` every change that turned `before` into `after` (an edit
// made in the panels of one side, mirrored on the other). The result is read
// back as strictly as a scene file.
Status mirrorEdit(const Scene& before, const Scene& after, Scene& other);

// The scene as its JSON document.
nlohmann::json sceneDocument(const Scene& scene);

// Sets the value at a JSON pointer ("/settings/sss/blur") and reads the scene
// back: the loader accepts it or says why not, so a value the panels offer
// but this build does not know is refused with the loader's message.
Status setSceneValue(Scene& scene, const std::string& pointer, const nlohmann::json& value);

// Writes `scene` as a scene file at `path`, with its map and mesh paths made
// relative to that file.
Status saveSceneJson(const Scene& scene, const std::string& path);

}  // namespace dermis::viewer
