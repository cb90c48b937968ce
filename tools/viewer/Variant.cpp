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
    Status status = mRenderer->renderFrame(request);
    if (!status.ok() && mRenderedSource && *mRenderedSource != mEdited.environment.source) {
        mRefusedEnvironment = status.error();
        mEdited.environment.source = *mRenderedSource;
        applySwitches(mEdited, switches, *mRendered);
        status = mRenderer->renderFrame(request);
    }
    if (!status.ok()) return status;
    mRenderedSource = mEdited.environment.source;
    mHistory.update(mRenderer->timings().summary());
    mRenderer->resetTimings();
    return success();
}

std::optional<Error> Variant::takeRefusedEnvironment() {
    std::optional<Error> refused;
    std::swap(refused, mRefusedEnvironment);
    return refused;
}

Status Variant::reloadShaders() {
    if (!mRenderer) {
        mCreateError.reset();  // the failure may have been a shader: try again on the next frame
        return success();
    }
    return mRenderer->reloadShaders();
}

}  // namespace dermis::viewer
