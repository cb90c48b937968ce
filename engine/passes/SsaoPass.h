#pragma once
// Pass 3: screen-space ambient occlusion (Papanikolaou 2013 §3.2; method and settings
// in shaders/ssao.frag) and its depth-aware bilateral blur
// (shaders/ssao_blur.frag), both at full resolution.
//
//   "ssao"       reads G-buffer depth, normal+material and albedo (object id);
//                creates "ao raw" (R8, 1 = unoccluded)
//   "ssao blur"  reads "ao raw" and the depth key; creates "ao" (R8)
//
// Both are skipped by predicate when settings.ssao.enabled is false, the
// strength is 0 or the scene has no characters; their outputs then pass
// through to `white`. With settings.ssao.blur false only the blur is skipped
// and "ao" passes through to "ao raw".

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"

namespace dermis {

// Shader constants the scene file does not expose (SsaoBlock; shaders/ssao.frag).
constexpr float kSsaoBiasFractionOfRadius = 0.02f;
constexpr float kSsaoRangeFadeEndRadii = 2.0f;
constexpr int kSsaoBlurHalfWidthPx = 2;  // a 5x5 box
constexpr float kSsaoBlurDepthTolerance = 0.05f;  // fraction of the view depth

// Returns the (blurred) AO texture, R8, 1 = unoccluded. `white` is an
// imported 1x1 white texture: the result when SSAO does not run.
graph::TextureHandle addSsaoPasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                   graph::TextureHandle white);

// The SsaoBlock both SSAO passes upload, from the scene's settings.
gpu::SsaoBlock makeSsaoBlock(const SsaoSettings& settings);

}  // namespace dermis
