// OSMesa: Mesa's off-screen renderer, the fallback when EGL fails.
#include "gl/Gl.h"
#include "gl/GlContext.h"

#include <GL/osmesa.h>

#include <vector>

namespace dermis::gl {
namespace {

void* osmesaLoader(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

class OsMesaContext final : public Context {
public:
    explicit OsMesaContext(OSMesaContext context) : mContext(context), mBuffer(4, 0) {}
    ~OsMesaContext() override { OSMesaDestroyContext(mContext); }
    std::string backendName() const override { return "osmesa"; }
    bool makeCurrent() { return OSMesaMakeCurrent(mContext, mBuffer.data(), GL_UNSIGNED_BYTE, 1, 1) != 0; }

private:
    OSMesaContext mContext;
    std::vector<unsigned char> mBuffer;  // a 1x1 default framebuffer; we draw into FBOs
};

}  // namespace

Result<std::unique_ptr<Context>> createOsMesaContext(bool debug) {
    (void)debug;  // OSMesa has no debug-context flag; KHR_debug still works
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 8,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 5,
                              0};
    OSMesaContext raw = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!raw) return makeError("osmesa", "OSMesaCreateContextAttribs refused a 4.5 core context");
    auto context = std::make_unique<OsMesaContext>(raw);
    if (!context->makeCurrent()) return makeError("osmesa", "OSMesaMakeCurrent failed");
    const Status loaded = loadGlFunctions(osmesaLoader, "osmesa");
    if (!loaded.ok()) return loaded.error();
    return std::unique_ptr<Context>(std::move(context));
}

}  // namespace dermis::gl
