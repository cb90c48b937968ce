#pragma once
// Pass 4: deferred lighting into diffuse irradiance (pre-scatter albedo^mix,
// energy-conserving) and specular, kept apart so specular is added after any
// SSS blur. AO darkens the ambient term only.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {

struct Lighting {
    graph::TextureHandle irradiance;  // RGBA16F
    graph::TextureHandle specular;    // RGBA16F
};

Lighting addLightingPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle ambientOcclusion);

// Binds shadow maps to units 4.. (every unit gets a texture: sampler arrays must be complete).
void bindShadowMaps(const FrameContext& frame, const graph::PassResources& resources,
                    const std::vector<graph::TextureHandle>& shadowMaps);

}  // namespace dermis
