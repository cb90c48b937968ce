#include "gl/GlContext.h"

#include "gl/Gl.h"
#include "gl/GlDebug.h"

namespace dermis::gl {
namespace {
void* gGetProcAddress(const char*) { return nullptr; }
void* (*gLoader)(const char*) = gGetProcAddress;
GLADapiproc loadThroughCurrent(const char* name) { return reinterpret_cast<GLADapiproc>(gLoader(name)); }
}  // namespace

std::string Context::renderer() const {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return text ? text : "unknown";
}

std::string Context::version() const {
    const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return text ? text : "unknown";
}

Status loadGlFunctions(void* (*getProcAddress)(const char*), const std::string& contextName) {
    gLoader = getProcAddress;
    const int version = gladLoadGL(loadThroughCurrent);
    if (version == 0) return makeError(contextName, "could not load OpenGL entry points");
    if (GLAD_VERSION_MAJOR(version) < 4 || (GLAD_VERSION_MAJOR(version) == 4 && GLAD_VERSION_MINOR(version) < 5)) {
        return makeError(contextName, "OpenGL " + std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                                          std::to_string(GLAD_VERSION_MINOR(version)) + " found, 4.5 core needed");
    }
    return success();
}

Result<std::unique_ptr<Context>> createHeadlessContext(const ContextOptions& options) {
    std::string attempts;
    if (options.backend != Backend::OsMesa) {
        auto egl = createEglContext(options.debug);
        if (egl.ok()) {
            if (options.debug) enableDebugOutput();
            return egl;
        }
        attempts += egl.error().message();
        if (options.backend == Backend::Egl) return makeError("GL context", "no OpenGL 4.5 context: " + attempts);
    }
    auto osmesa = createOsMesaContext(options.debug);
    if (osmesa.ok()) {
        if (options.debug) enableDebugOutput();
        return osmesa;
    }
    if (!attempts.empty()) attempts += "; ";
    attempts += osmesa.error().message();
    return makeError("GL context", "no OpenGL 4.5 context: " + attempts);
}

}  // namespace dermis::gl
