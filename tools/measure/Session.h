#pragma once
// What every GL measurement starts with: a scene file, a headless context and
// a renderer for it.

#include "core/Result.h"
#include "gl/GlContext.h"
#include "render/FrameTimings.h"
#include "frame/Renderer.h"
#include "scene/Scene.h"

#include <memory>
#include <string>

namespace dermis::measure {

struct Session {
    std::unique_ptr<Scene> scene;
    std::unique_ptr<gl::Context> context;
    std::unique_ptr<Renderer> renderer;
    bool glDebug = false;

    // `overrides` are --set PATH=VALUE strings (scene/SceneOverrides.h).
    static Result<Session> open(const std::string& scenePath, const std::vector<std::string>& overrides,
                                gl::Backend backend, bool glDebug);
    Status checkGlErrors() const;  // with --gl-debug: any driver error is a failure
    RunInfo runInfo(const std::string& scenePath, int width, int height, int frames) const;
};


// Print "error: <where>: <what>" and return the exit status.

}  // namespace dermis::measure
