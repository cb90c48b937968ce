#include "viewer/Variant.h"

namespace dermis::viewer {

Variant::Variant(Scene scene) : mEdited(std::move(scene)), mRendered(std::make_unique<Scene>(mEdited)) {}

Status Variant::render(const FrameRequest& request, const EffectSwitches& switches) {
    applySwitches(mEdited, switches, *mRendered);
    if (mCreateError) return *mCreateError;
    if (!mRenderer) {
        auto renderer = Renderer::create(*mRendered);
        if (!renderer.ok()) {
            mCreateError = renderer.error();
            return *mCreateError;
        }
        mRenderer = std::move(*renderer);
    }
    if (const Status status = mRenderer->renderFrame(request); !status.ok()) return status;
    mHistory.update(mRenderer->timings().summary());
    mRenderer->resetTimings();
    return success();
}

Status Variant::reloadShaders() {
    if (!mRenderer) {
        mCreateError.reset();  // the failure may have been a shader: try again on the next frame
        return success();
    }
    return mRenderer->reloadShaders();
}

}  // namespace dermis::viewer
