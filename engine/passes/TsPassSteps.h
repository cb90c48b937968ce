#pragma once
// The texture-space passes of one character, one function each (the order
// and names are in TextureSpacePasses.h). Internal to passes/.

#include "graph/RenderGraph.h"
#include "passes/GBufferPass.h"
#include "render/FrameContext.h"
#include "plan/TsPlan.h"

#include <string>
#include <vector>

namespace dermis {

// The per-character TextureSpaceBlock; passes add their own fields (blur).
gpu::TextureSpaceBlock textureSpaceBlock(const FrameContext& frame, const TsCharacterPlan& plan);
// Uploads the character's ObjectBlock and `block`.
void uploadTsBlocks(const FrameContext& frame, const TsCharacterPlan& plan, const gpu::TextureSpaceBlock& block);
enum class TsDraw {
    Surface,          // the surface's submeshes, each with its ObjectBlock
    SurfaceWithMaps,  // and its material's maps bound (bindMaterialMaps, and the LEAN map at DERMIS_UNIT_TS_LEAN_MAP)
    WholeCharacter,   // every triangle, one draw, with the ObjectBlock already uploaded
};
// Draws the character's TsMesh.
void drawTsMesh(const FrameContext& frame, const TsCharacterPlan& plan, TsDraw what);
std::string tsPassName(const TsCharacterPlan& plan, const std::string& step);

graph::TextureHandle addTsmPass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                graph::TextureHandle black);
// The texels of surface inside the body (mesh/UvLayout.h buried): empty in
// a frame, so that the blurs leave them out; lit in the capture for the
// reference (frame/IrradianceCapture.h), which leaves that surface out
// itself and would read an empty texel beside the junction as no light.
enum class BuriedTexels { Empty, Lit };
graph::TextureHandle addIrradiancePass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                       const GBuffer& gbuffer, const std::vector<graph::TextureHandle>& shadowMaps,
                                       graph::TextureHandle ambientOcclusion, graph::TextureHandle tsm,
                                       BuriedTexels buried = BuriedTexels::Empty);
graph::TextureHandle addDilatePass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                   graph::TextureHandle irradiance);
// One texture per Gaussian step, the first blurred from `dilated` (a skipped
// step's texture is the previous one), with FramePlan::tsKernel.
std::vector<graph::TextureHandle> addBlurPasses(graph::RenderGraph& graph, const FrameContext& frame,
                                                const TsCharacterPlan& plan, graph::TextureHandle stretch,
                                                graph::TextureHandle dilated);

}  // namespace dermis
