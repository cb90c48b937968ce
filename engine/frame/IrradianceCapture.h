#pragma once
// The texture-space irradiance texture of every SSS character, read back to
// the CPU (Renderer::captureIrradianceTextures): what the CPU reference
// scatters to compare with the engine on the engine's own light.
//
// declareIrradianceCapture adds the passes that texture needs (shadow maps,
// G-buffer and SSAO for the ambient term, each character's TSM and
// irradiance pass, as the ts frame declares them but with the surface inside
// the body lit: passes/TsPassSteps.h BuriedTexels) and one read-back
// pass per character. The caller plans the frame with the texture size it
// wants and every SSS character visible (plan/TsPlan.h).

#include "core/Image.h"
#include "graph/RenderGraph.h"
#include "render/FrameInputs.h"
#include "plan/FramePlan.h"

#include <vector>

namespace dermis {

// The sides Renderer::captureIrradianceTextures accepts (powers of two).
constexpr int kMinIrradianceCaptureTexels = 64;
constexpr int kMaxIrradianceCaptureTexels = 8192;

// `images` gets one entry per scene character: RGBA linear floats, row y at
// v = (y + 0.5) / side (not flipped: row 0 is v near 0), column x at
// u = (x + 0.5) / side, in the mesh's raw TEXCOORD_0; alpha > 0 on covered
// texels, 0 on empty ones; empty for a character that plan.ts does not hold.
// The images are filled when the graph executes.
void declareIrradianceCapture(graph::RenderGraph& graph, const FramePlan& plan, const FrameInputs& inputs,
                              std::vector<Image>& images);

}  // namespace dermis
