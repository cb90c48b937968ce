#pragma once
// One side of the A/B comparison: the scene its panels edit, the scene its
// renderer reads (the edited one with the effect switches applied, rebuilt
// every frame) and the renderer itself, created on first use so that the B
// side costs nothing until the split or difference view asks for it.

#include "core/Result.h"
#include "frame/Renderer.h"
#include "scene/Scene.h"
#include "viewer/EffectSwitches.h"
#include "viewer/PassHistory.h"

#include <memory>
#include <optional>
#include <string>

namespace dermis::viewer {

class Variant {
public:
    explicit Variant(Scene scene);
    Variant(const Variant&) = delete;
    Variant& operator=(const Variant&) = delete;

    Scene& edited() { return mEdited; }
    const Scene& edited() const { return mEdited; }

    // Applies the switches, creates the renderer when there is none yet, renders
    // and folds the frame's timings into history(). An edited environment
    // source that fails to load is undone (the renderer keeps the map it had)
    // and the frame rendered again; takeRefusedEnvironment() then says why.
    Status render(const FrameRequest& request, const EffectSwitches& switches);
    // The latest refused environment source, once; none when there was none since the last call.
    std::optional<Error> takeRefusedEnvironment();
    bool hasRenderer() const { return mRenderer != nullptr; }
    GLuint outputTexture() const { return mRenderer ? mRenderer->outputTexture() : 0; }
    // The rendered scene's meshes and rigs; null before the renderer exists.
    const SceneGeometry* geometry() const { return mRenderer ? &mRenderer->geometry() : nullptr; }
    // Each character as its last frame planned it (empty before the first frame).
    std::vector<CharacterReport> characterReports() const {
        return mRenderer ? mRenderer->characterReports() : std::vector<CharacterReport>{};
    }
    // Recompiles the shaders; a renderer not created yet will read them when it is.
    Status reloadShaders();

    PassHistory& history() { return mHistory; }
    const PassHistory& history() const { return mHistory; }

private:
    Scene mEdited;
    // Declared before the renderer, which keeps a reference to it: destroyed after it.
    std::unique_ptr<Scene> mRendered;
    std::unique_ptr<Renderer> mRenderer;
    std::optional<Error> mCreateError;  // a renderer that failed to load is not retried every frame
    std::optional<std::string> mRenderedSource;  // the environment source of the latest frame rendered
    std::optional<Error> mRefusedEnvironment;
    PassHistory mHistory;
};

}  // namespace dermis::viewer
