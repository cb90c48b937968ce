#pragma once
// The skybox (docs/environment.md): the environment map drawn behind
// everything into the HDR colour, after the composite, at the pixels the
// G-buffer left empty (a far-plane triangle and a depth test, so covered
// pixels cost no shading). Culled, with its reason, when the frame has no
// environment, the scene draws its background colour instead, or the output
// is not a colour image.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

namespace dermis {

// Returns hdr's new version (hdr itself when culled at declaration).
graph::TextureHandle addSkyboxPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                   graph::TextureHandle hdr);

}  // namespace dermis
