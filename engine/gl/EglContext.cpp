// EGL: hardware device first, then Mesa surfaceless.
#include "gl/Gl.h"
#include "gl/GlContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>
#include <vector>

namespace dermis::gl {
namespace {

constexpr int kMaxDevices = 16;

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const size_t length = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += length) {
        if ((p == list || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0')) return true;
    }
    return false;
}

std::string eglErrorName(EGLint code) {
    switch (code) {
        case EGL_SUCCESS: return "EGL_SUCCESS";
        case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
        case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
        case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
        case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
        case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
        case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
        case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
        default: return "EGL error " + std::to_string(code);
    }
}

void* eglLoader(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context, std::string name)
        : mDisplay(display), mContext(context), mName(std::move(name)) {}
    ~EglContext() override {
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(mDisplay, mContext);
        eglTerminate(mDisplay);
    }
    std::string backendName() const override { return mName; }

private:
    EGLDisplay mDisplay;
    EGLContext mContext;
    std::string mName;
};

// Makes a 4.5 core context current on an initialised display, or says why not.
Result<std::unique_ptr<Context>> makeContext(EGLDisplay display, const std::string& name, bool debug) {
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(display, &major, &minor)) return makeError(name, "eglInitialize failed (" + eglErrorName(eglGetError()) + ")");
    auto fail = [&](const std::string& why) -> Result<std::unique_ptr<Context>> {
        eglTerminate(display);
        return makeError(name, why);
    };
    if (!hasExtension(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context")) {
        return fail("EGL_KHR_surfaceless_context missing");
    }
    if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API) failed");
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    const bool haveConfig = eglChooseConfig(display, configAttributes, &config, 1, &configCount) && configCount > 0;
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                                        EGL_CONTEXT_MINOR_VERSION, 5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_CONTEXT_OPENGL_DEBUG, debug ? EGL_TRUE : EGL_FALSE,
                                        EGL_NONE};
    EGLContext context = eglCreateContext(display, haveConfig ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (context == EGL_NO_CONTEXT) return fail("no OpenGL 4.5 core context (" + eglErrorName(eglGetError()) + ")");
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        return fail("eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")");
    }
    std::unique_ptr<Context> result = std::make_unique<EglContext>(display, context, name);
    const Status loaded = loadGlFunctions(eglLoader, name);
    if (!loaded.ok()) return loaded.error();
    return result;
}

Result<std::unique_ptr<Context>> tryHardwareDevice(bool debug) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        return makeError("egl-device", "EGL_EXT_platform_device not supported");
    }
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!queryDevices || !queryDeviceString || !getPlatformDisplay) {
        return makeError("egl-device", "device enumeration entry points missing");
    }
    EGLDeviceEXT devices[kMaxDevices];
    EGLint count = 0;
    if (!queryDevices(kMaxDevices, devices, &count) || count == 0) return makeError("egl-device", "no EGL devices");
    std::string reasons;
    for (EGLint i = 0; i < count; ++i) {
        const char* deviceExtensions = queryDeviceString(devices[i], EGL_EXTENSIONS);
        if (hasExtension(deviceExtensions, "EGL_MESA_device_software")) continue;  // llvmpipe: use surfaceless
        EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display == EGL_NO_DISPLAY) continue;
        auto context = makeContext(display, "egl-device", debug);
        if (context.ok()) return context;
        reasons += (reasons.empty() ? "" : ", ") + context.error().what;
    }
    return makeError("egl-device", reasons.empty() ? "no hardware EGL device" : reasons);
}

Result<std::unique_ptr<Context>> trySurfaceless(bool debug) {
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        return makeError("egl-surfaceless", "EGL_MESA_platform_surfaceless not supported");
    }
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!getPlatformDisplay) return makeError("egl-surfaceless", "eglGetPlatformDisplayEXT missing");
    EGLDisplay display = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) return makeError("egl-surfaceless", "no display");
    return makeContext(display, "egl-surfaceless", debug);
}

}  // namespace

Result<std::unique_ptr<Context>> createEglContext(bool debug) {
    auto device = tryHardwareDevice(debug);
    if (device.ok()) return device;
    auto surfaceless = trySurfaceless(debug);
    if (surfaceless.ok()) return surfaceless;
    return makeError("EGL", "tried " + device.error().message() + "; " + surfaceless.error().message());
}

}  // namespace dermis::gl
