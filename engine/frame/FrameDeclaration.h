#pragma once
// Declares the frame's passes into a render graph from its plan
// (plan/FramePlan.h) and the backend textures the graph imports. It does no
// GL work and cannot fail: every decision was made by the plan, and the
// graph's compile() culls what the plan says is not needed. On the test
// backend (graph/TestBackend.h) the inputs' textures are 0 and `services` is
// null, and compile() + passReports() tell which passes of the real frame run
// and why the others are culled.
//
// The frame (Jimenez et al. 2009, d'Eon & Luebke 2007):
//   shadow maps -> gbuffer -> ssao -> lighting -> transmittance
//     -> SSS chain (screen space, or texture space in "ts" mode)
//     -> composite -> tonemap, or -> aov for any other AOV.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"
#include "render/FrameInputs.h"
#include "plan/FramePlan.h"

#include <vector>

namespace dermis {

void declareFrame(graph::RenderGraph& graph, const FramePlan& plan, const FrameInputs& inputs);

}  // namespace dermis
