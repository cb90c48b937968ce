#pragma once
// Texture-space SSS, the "ts" mode (d'Eon & Luebke 2007;
// shaders/include/TextureSpace.glsl is the method's manual, plan/TsPlan.h
// decides what runs, FramePlan::ts holds the decisions). It takes the place
// of the screen-space chain
// (SssPasses.h) and returns what the composite reads in its stead:
//
//   ts init                    the accumulation starts as the lighting's irradiance
//   per SSS character <c> (its pass-name label, TsCharacterPlan::label):
//   ts <c> tsm                 its modified translucent shadow map (Chappuis 2011 §2.5)
//   ts <c> stretch             stretch map in its UV layout (§2.2.4, listing 2.1)
//   ts <c> irradiance          irradiance texture in its UV layout (§2.2.3)
//   ts <c> dilate              chart gutters filled
//   ts <c> g<i> u, g<i> v      texture i = texture i-1 blurred by v_i - v_(i-1) (§2.2.4);
//                              Gaussian 0 is skipped (the irradiance itself) but in close-ups
//   ts <c> gather              its pixels of the accumulation (§2.8)
//
// A character off screen has every one of its passes skipped by predicate;
// with none on screen "ts init" is skipped too and the composite reads the
// irradiance itself (passThrough). Textures are the graph's transients
// (pooled); what lives across frames (the meshes' UV-layout buffers,
// render/TsMeshes.h) is made by the prepare step (render/FrameResources.h).
//
// The screen-space transmittance pass is not read in this mode (the TSM
// carries light through thin regions instead), so the graph culls it.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "plan/Aov.h"
#include "render/FrameContext.h"
#include "plan/TsPlan.h"

#include <vector>

namespace dermis {

// c in the stored exp(-c d) of the thickness (1/mm): 50 mm (the front) is
// e^-5, well inside fp16 (Chappuis 2011 listing 2.7 uses 0.1 in its units).
constexpr float kTsThicknessPerMm = 0.1f;

// The TSM terms use this many of a profile's widest Gaussians (Chappuis 2011
// listing 2.11: three of six).
constexpr int kTsmGaussians = 3;

// Declares the passes of FramePlan::ts. `irradiance` is the lighting pass's
// diffuse irradiance (before the screen-space transmittance); `base` what the
// accumulation starts from: the same irradiance, or the screen-space chain's
// result when a character falls back to it (plan/TsPlan.h); `black` an
// imported 1x1 black texture (the TSM of a character without one).
graph::TextureHandle addTextureSpacePasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                           const std::vector<graph::TextureHandle>& shadowMaps,
                                           graph::TextureHandle ambientOcclusion, graph::TextureHandle irradiance,
                                           graph::TextureHandle base, graph::TextureHandle hiddenSide,
                                           graph::TextureHandle black);

// The UV-space AOVs (plan/Aov.h), in either SSS mode: the stretch map, or
// the irradiance texture before dilation and blurs, of the first SSS character
// on screen. Only the passes that texture needs are declared (stretch; tsm and
// irradiance), so in screen-space mode nothing else of this mode runs. `none`
// when no SSS character is on screen (or SSS is off).
graph::TextureHandle addTsAovPasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                    const std::vector<graph::TextureHandle>& shadowMaps,
                                    graph::TextureHandle ambientOcclusion, graph::TextureHandle none);

// The stretch pass alone, for tests of it: the stretch map of `plan`'s character.
graph::TextureHandle addTsStretchPass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan);

}  // namespace dermis
