#pragma once
// The LEAN specular (variants lcb and lbb, plan/SssVariant.h; the method is
// shaders/include/Lean.glsl, the per-pixel sum shaders/include/LeanLights.glsl):
// after the SSS chain, the specular of characters with LEAN maps from their
// blurred view-plane moments, with the lighting pass's shadow visibility;
// other pixels keep the lighting pass's specular. The final image computes it
// inside the composite (CompositePass.h, LeanShading); this pass writes it
// out on its own for the specular AOV. Variant c declares neither.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

namespace dermis {

// What the LEAN specular reads besides the G-buffer.
struct LeanShading {
    graph::TextureHandle moments;      // blurred GBuffer::leanMoments
    graph::TextureHandle accumulated;  // SSS-accumulated irradiance: alpha = blurred GBuffer::leanCross
    graph::TextureHandle visibility;   // Lighting::visibility

    bool isValid() const { return moments.isValid(); }
};

// Returns the specular (RGBA16F): LEAN where the character has LEAN maps,
// `lightingSpecular` elsewhere.
graph::TextureHandle addLeanSpecularPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                         const LeanShading& lean, graph::TextureHandle lightingSpecular);

}  // namespace dermis
