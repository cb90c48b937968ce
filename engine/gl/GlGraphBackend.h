#pragma once
// The render graph's GL backend: pooled transient textures, and around every
// executed pass a KHR_debug group plus a GPU/CPU timer scope. Passes never
// time themselves.

#include "gl/FramebufferCache.h"
#include "gl/GpuProfiler.h"
#include "gl/TexturePool.h"
#include "graph/GraphBackend.h"

namespace dermis::gl {

class GlGraphBackend final : public graph::GraphBackend {
public:
    explicit GlGraphBackend(GpuProfiler& profiler) : mProfiler(profiler) {}

    graph::BackendTexture acquireTexture(const graph::TextureDesc& desc, std::string_view debugName) override;
    void releaseTexture(graph::BackendTexture texture, const graph::TextureDesc& desc) override;
    void beginPass(std::string_view passName) override;
    void endPass() override;

    TexturePool& pool() { return mPool; }
    FramebufferCache& framebuffers() { return mFramebuffers; }
    void endFrame();  // recycles stale pool textures and their framebuffers

private:
    GpuProfiler& mProfiler;
    TexturePool mPool;
    FramebufferCache mFramebuffers;
};

}  // namespace dermis::gl
