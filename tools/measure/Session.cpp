#include "measure/Session.h"

#include "core/Log.h"
#include "gl/GlDebug.h"
#include "scene/SceneLoader.h"

namespace dermis::measure {

Result<Session> Session::open(const std::string& scenePath, const std::vector<std::string>& overrides,
                              gl::Backend backend, bool glDebug) {
    Session session;
    session.glDebug = glDebug;
    auto scene = loadScene(scenePath, overrides);
    if (!scene.ok()) return scene.error();
    session.scene = std::make_unique<Scene>(std::move(*scene));
    if (const std::string unlit = unlitSceneReason(*session.scene); !unlit.empty()) log::warn(scenePath + ": " + unlit);
    auto context = gl::createHeadlessContext({backend, glDebug});
    if (!context.ok()) return context.error();
    session.context = std::move(*context);
    auto renderer = Renderer::create(*session.scene);
    if (!renderer.ok()) return renderer.error();
    session.renderer = std::move(*renderer);
    return session;
}

Status Session::checkGlErrors() const {
    // Out of memory is reported with or without --gl-debug: a target the driver
    // could not allocate leaves the frame undefined, often black.
    if (gl::drainGlErrorsNoting().outOfMemory)
        return makeError("OpenGL", "the driver ran out of memory (GL_OUT_OF_MEMORY) for this frame's targets; try a smaller --size");
    if (glDebug && gl::debugErrorCount() > 0) {
        return makeError("OpenGL", std::to_string(gl::debugErrorCount()) + " error(s), last: " + gl::lastDebugError());
    }
    return success();
}

RunInfo Session::runInfo(const std::string& scenePath, int width, int height, int frames) const {
    RunInfo info;
    info.renderer = context->renderer();
    info.backend = context->backendName();
    info.glVersion = context->version();
    info.scene = scenePath;
    info.width = width;
    info.height = height;
    info.frames = frames;
    return info;
}

}  // namespace dermis::measure
