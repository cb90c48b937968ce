#pragma once
// Back-normal transmittance (Papanikolaou 2013 §4.3; shaders/include/Transmittance.glsl),
// added into `target` by blending, before the SSS blur so it is softened too.
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
