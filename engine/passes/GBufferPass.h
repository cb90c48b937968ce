#pragma once
// Pass 2: the G-buffer (layout in shaders/gbuffer.frag). The stencil holds
// each pixel's SSS profile id so later blurs can be confined to skin.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

namespace dermis {

struct GBuffer {
    graph::TextureHandle depthStencil;    // D24S8
    graph::TextureHandle albedo;          // RGBA8 sRGB
    graph::TextureHandle normalMaterial;  // RGBA16F
};

GBuffer addGBufferPass(graph::RenderGraph& graph, FrameContext& frame);

}  // namespace dermis
