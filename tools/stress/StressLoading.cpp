#include "stress/StressLoading.h"

#include "core/TextFile.h"
#include "scene/SceneLoader.h"

namespace dermis::stress {

Result<Scene> loadCaseScene(const StressCase& c) {
    const std::string json = sceneToJson(c.scene);
    if (c.path == CasePath::Memory) return parseScene(json, c.scene.path);
    if (const Status written = writeTextFileAtomically(c.scene.path, json); !written.ok()) return written.error();
    return loadScene(c.scene.path, c.overrides);
}

std::string refusalProblem(const StressCase& c, const Result<Scene>& loaded) {
    if (loaded.ok()) return "the loader accepted a value it must refuse";
    const std::string message = loaded.error().message();
    const std::string source = c.refusal.throughOverride ? "--set " + c.overrides.back() : c.scene.path;
    for (const std::string& part : {source, c.refusal.key, c.refusal.range}) {
        if (message.find(part) == std::string::npos) return "the refusal does not name \"" + part + "\": " + message;
    }
    return {};
}

}  // namespace dermis::stress
