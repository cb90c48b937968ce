#include "gl/GlDebug.h"

#include "core/Log.h"
#include "gl/Gl.h"

#include <atomic>
#include <mutex>

namespace dermis::gl {
namespace {
std::atomic<uint64_t> gErrors{0};
std::mutex gMutex;
std::string gLastError;

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void* user) {
    (void)source;
    (void)id;
    (void)user;
    const std::string text(message, length > 0 ? static_cast<size_t>(length) : 0);
    if (type == GL_DEBUG_TYPE_ERROR) {
        ++gErrors;
        std::lock_guard<std::mutex> lock(gMutex);
        gLastError = text;
        log::error("GL: " + text);
    } else if (severity == GL_DEBUG_SEVERITY_HIGH || severity == GL_DEBUG_SEVERITY_MEDIUM) {
        log::warn("GL: " + text);
    }
}
}  // namespace

void enableDebugOutput() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    // Push/pop group notifications are noise.
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_POP_GROUP, GL_DONT_CARE, 0, nullptr, GL_FALSE);
}

uint64_t debugErrorCount() { return gErrors; }

std::string lastDebugError() {
    std::lock_guard<std::mutex> lock(gMutex);
    return gLastError;
}

DrainedGlErrors drainGlErrorsNoting() {
    DrainedGlErrors drained;
    for (GLenum error = glGetError(); error != GL_NO_ERROR && drained.count < 64; error = glGetError()) {
        ++drained.count;
        drained.outOfMemory = drained.outOfMemory || error == GL_OUT_OF_MEMORY;
        std::lock_guard<std::mutex> lock(gMutex);
        gLastError = "glGetError " + std::to_string(error);
    }
    gErrors += drained.count;
    return drained;
}

uint64_t drainGlErrors() { return drainGlErrorsNoting().count; }

}  // namespace dermis::gl
