#pragma once
// Light carried through thin regions from the lit surface behind them
// (shaders/include/Transmittance.glsl), added into `target` by blending:
// screen space adds it before the SSS blur, texture space into its gathered light.
// Runs on SSS pixels only (stencil) inside the SSS scissor. Skipped by
// predicate when no shadowed light is behind any visible SSS character.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {


// Adds into `addInto` (the irradiance) and returns its new version; with an
// invalid `addInto` it writes a texture of its own, cleared first (for the
// transmittance AOV), falling back to `black` when the pass is skipped.
graph::TextureHandle addTransmittancePass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                          const std::vector<graph::TextureHandle>& shadowMaps,
                                          graph::TextureHandle addInto, graph::TextureHandle black);

}  // namespace dermis
