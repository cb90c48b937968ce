#pragma once
// The shadow maps: one pass per shadow-casting light (FramePlan::shadows).
// Renders the characters the plan keeps for the light (ShadowSlotPlan::casters,
// plan/ShadowCasters.h) into its map as linear depth along the light's axis
// (metres). Skipped by its predicate when the plan found the cached map
// current (plan/ShadowCache.h), or when no character is on screen to
// receive the shadow.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {

// `maps` are the backend's shadow maps, one per FramePlan::shadows entry (0 on
// the test backend). Returns one handle per shadow slot.
std::vector<graph::TextureHandle> addShadowPasses(graph::RenderGraph& graph, const FrameContext& frame,
                                                  const std::vector<graph::BackendTexture>& maps);

}  // namespace dermis
