#pragma once
// Widgets for scene keys edited through the scene's JSON form, each change
// read back by the strict loader (SceneJson.h). They cover what the typed
// panels do not: keys added to the scene format after the viewer was
// written (the texture-space settings, the LEAN variant ...) appear here by
// themselves, with widgets chosen by their JSON type.

#include "scene/Scene.h"

#include <string>
#include <vector>

namespace dermis::viewer {

// Every key of the object at `pointer` ("/settings/sss") except those in
// `skip`; nested objects become tree nodes. Returns true when the scene
// changed; a refused edit leaves it as it was and sets `error`.
bool jsonFields(Scene& scene, const std::string& pointer, const std::vector<std::string>& skip, std::string& error);

// The keys of the object at `pointer` that jsonFields would show.
std::vector<std::string> jsonFieldKeys(const Scene& scene, const std::string& pointer, const std::vector<std::string>& skip);

// One string key chosen from the words it may take (sss.blur, shadow.filter,
// mode ...); a word this build's loader refuses sets `error`.
bool jsonChoice(Scene& scene, const std::string& pointer, const char* label, std::string& error);

}  // namespace dermis::viewer
