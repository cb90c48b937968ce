#pragma once
// The render graph's GL backend: pooled transient textures, and around every
// executed pass a KHR_debug group plus a GPU/CPU timer scope. Passes never
// time themselves.

#include "gl/FramebufferCache.h"
#include "gl/GpuProfiler.h"
#include "gl/SanitiseCounters.h"
#include "gl/TexturePool.h"
#include "graph/GraphBackend.h"

#include <functional>
#include <string>
#include <vector>

namespace dermis::gl {

// Called with every texture a pass wrote, when set (GlGraphBackend::setInspector).
using PassInspector = std::function<void(std::string_view pass, std::string_view texture, GLuint name,
                                         const graph::TextureDesc& desc)>;

class GlGraphBackend final : public graph::GraphBackend {
public:
    explicit GlGraphBackend(GpuProfiler& profiler) : mProfiler(profiler) {}

    graph::BackendTexture acquireTexture(const graph::TextureDesc& desc, std::string_view debugName) override;
    void releaseTexture(graph::BackendTexture texture, const graph::TextureDesc& desc) override;
    void beginPass(std::string_view passName) override;
    void endPass() override;
    void passWrote(std::string_view passName, std::string_view textureName, graph::BackendTexture texture,
                   const graph::TextureDesc& desc) override;
    void setInspector(PassInspector inspector) { mInspector = std::move(inspector); }

    TexturePool& pool() { return mPool; }
    FramebufferCache& framebuffers() { return mFramebuffers; }
    SanitiseCounters& sanitiseCounters() { return mSanitise; }
    // The passes of the last executed frame, in order.
    const std::vector<std::string>& framePasses() const { return mFramePasses; }
    void endFrame();  // recycles stale pool textures and their framebuffers

private:
    GpuProfiler& mProfiler;
    TexturePool mPool;
    FramebufferCache mFramebuffers;
    PassInspector mInspector;
    SanitiseCounters mSanitise;
    std::vector<std::string> mFramePasses;
    bool mFrameEnded = true;
};

}  // namespace dermis::gl
