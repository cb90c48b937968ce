#pragma once
// Pass 2: the G-buffer (layout in shaders/gbuffer.frag). The stencil holds
// each pixel's SSS profile slot so later blurs can be confined to skin.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

namespace dermis {

struct GBuffer {
    graph::TextureHandle depthStencil;    // D24S8; stencil = SSS profile slot (0 = opaque)
    graph::TextureHandle albedo;          // RGBA8 sRGB; alpha = object id / 255
    graph::TextureHandle normalMaterial;  // RGBA16F: octahedral view normal, roughness m, rho_s
    graph::TextureHandle depthKey;        // R32UI: profile slot and view depth (UniformBlocks.glsl)
};

GBuffer addGBufferPass(graph::RenderGraph& graph, FrameContext& frame);

}  // namespace dermis
