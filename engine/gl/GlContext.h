#pragma once
// Headless OpenGL 4.5 core contexts.
//
// Backend::Egl tries, in order:
//   1. EGL device platform (EGL_EXT_platform_device) on a hardware device;
//   2. Mesa's surfaceless platform (EGL_MESA_platform_surfaceless): llvmpipe
//      on a machine without a GPU.
// Backend::OsMesa uses Mesa's off-screen library. Backend::Auto is EGL, then
// OSMesa. When everything fails the error lists every attempt and why.
//
// Rendering always targets framebuffer objects, so no context has a
// default framebuffer worth drawing to.

#include "core/Result.h"

#include <memory>
#include <string>

namespace dermis::gl {

enum class Backend { Auto, Egl, OsMesa };

struct ContextOptions {
    Backend backend = Backend::Auto;
    bool debug = false;  // GL debug context + KHR_debug callback
};

class Context {
public:
    virtual ~Context() = default;
    virtual std::string backendName() const = 0;  // "egl-device", "egl-surfaceless", "osmesa", "glfw"
    std::string renderer() const;                 // GL_RENDERER
    std::string version() const;                  // GL_VERSION
};

Result<std::unique_ptr<Context>> createHeadlessContext(const ContextOptions& options);

// Internal: each platform's attempt. Errors say what was tried.
Result<std::unique_ptr<Context>> createEglContext(bool debug);
Result<std::unique_ptr<Context>> createOsMesaContext(bool debug);

// After a context is current: load GL entry points and check for 4.5 core.
Status loadGlFunctions(void* (*getProcAddress)(const char*), const std::string& contextName);

}  // namespace dermis::gl
