#pragma once
// The LEAN specular pass (variants lcb and lbb, render/SssVariant.h; the
// method is shaders/include/Lean.glsl): after the SSS chain, the specular of
// characters with LEAN maps from their blurred view-plane moments, with the
// lighting pass's shadow visibility; other pixels keep the lighting pass's
// specular. Its output replaces that specular for the composite and the
// specular AOV. Variant c declares no such pass.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

namespace dermis {

struct LeanSpecularInputs {
    GBuffer gbuffer;
    graph::TextureHandle moments;     // blurred GBuffer::leanMoments
    graph::TextureHandle cross;       // blurred GBuffer::leanCross
    graph::TextureHandle visibility;  // Lighting::visibility
    graph::TextureHandle specular;    // Lighting::specular
};

graph::TextureHandle addLeanSpecularPass(graph::RenderGraph& graph, FrameContext& frame, const LeanSpecularInputs& in);

}  // namespace dermis
