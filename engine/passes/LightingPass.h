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
    graph::TextureHandle irradiance;  // RGBA16F; alpha 1, or the LEAN cross moment when the G-buffer has LEAN targets
    graph::TextureHandle specular;    // RGBA16F
    graph::TextureHandle visibility;  // RGBA8: shadow visibility per shadow slot; only when asked for
};

// shadowVisibility: also write each shadowed light's visibility, for a later
// pass that shades with the same shadows (the LEAN specular). With LEAN
// targets in the G-buffer the irradiance's alpha carries GBuffer::leanCross
// into the SSS chain.
Lighting addLightingPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle ambientOcclusion,
                         bool shadowVisibility = false);

// Binds shadow maps to units 4.. (every unit gets a texture: sampler arrays must be complete).
void bindShadowMaps(const FrameContext& frame, const graph::PassResources& resources,
                    const std::vector<graph::TextureHandle>& shadowMaps);

}  // namespace dermis
