#pragma once
// The light past the outline of a thin part (shaders/include/ThinEdges.glsl):
// a depth-only draw of the visible characters' back faces, then, per SSS
// pixel, the hidden side's light and the fill's weight from the view ray's
// path through the part. Every screen-space technique and the texture-space
// gather read the result at DERMIS_UNIT_HIDDEN_SIDE.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {

// The hidden-side target (RGBA16F), or `black` (1x1, a weight of 0: no fill)
// when the passes are culled: transmittance.thin_edges off, SSS off, or no
// SSS pixel on screen.
graph::TextureHandle addThinEdgePasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                       const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle black);

}  // namespace dermis
