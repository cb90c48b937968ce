#pragma once
// Writes the requested AOV (plan/Aov.h), linear, into `output` (an imported
// RGBA32F texture). Only the inputs that AOV needs are read, so the graph
// culls every pass the AOV does not depend on.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

namespace dermis {

struct AovInputs {
    GBuffer gbuffer;
    graph::TextureHandle diffuse;    // SSS-accumulated irradiance (diffuse AOV)
    graph::TextureHandle specular;
    graph::TextureHandle component;  // irradiance, AO or transmittance: read as the AOV itself
    graph::TextureHandle unscattered;  // the lighting pass's irradiance, which the diffuse AOV mixes in by s
};

graph::TextureHandle addAovPass(graph::RenderGraph& graph, const FrameContext& frame, const AovInputs& inputs,
                                graph::TextureHandle output);

}  // namespace dermis
