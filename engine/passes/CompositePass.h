#pragma once
// Pass 6: composite (SSS-accumulated irradiance x albedo^(1-mix) x outgoing
// energy + specular, background), then tone mapping into the 8-bit output.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "passes/LeanSpecularPass.h"
#include "passes/LightingPass.h"
#include "render/FrameContext.h"

namespace dermis {

// With `lean` (variants lcb and lbb) the specular of characters with LEAN
// maps is computed here from the blurred moments (LeanSpecularPass.h), and
// `specular` serves the others. `unscattered` (the lighting pass's irradiance)
// is mixed with `diffuse` by the G-buffer's scattering share
// (include/OutgoingDiffuse.glsl).
graph::TextureHandle addCompositePass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                      graph::TextureHandle diffuse, graph::TextureHandle unscattered,
                                      graph::TextureHandle specular,
                                      const LeanShading& lean = {});

// Writes tone-mapped sRGB into `output` (an imported RGBA8 texture).
graph::TextureHandle addTonemapPass(graph::RenderGraph& graph, const FrameContext& frame, graph::TextureHandle hdr,
                                    graph::TextureHandle output);

}  // namespace dermis
