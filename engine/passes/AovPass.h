#pragma once
// Writes the requested AOV (render/Aov.h), linear, into `output` (an imported
// RGBA32F texture). Only the inputs that AOV needs are read, so the graph
// culls every pass the AOV does not depend on.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "passes/LightingPass.h"
#include "render/FrameContext.h"

namespace dermis {

graph::TextureHandle addAovPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                const Lighting& lighting, graph::TextureHandle output);

}  // namespace dermis
