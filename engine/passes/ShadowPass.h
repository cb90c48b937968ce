#pragma once
// Pass 1 (DESIGN.md): one per shadow-casting light. Renders every character
// into the light's map as linear depth along the light's axis (metres).
// Skipped by its predicate when the cached map is still current.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"
#include "render/ShadowCache.h"

#include <vector>

namespace dermis {

// Returns one handle per shadow slot (in LightSetup::shadowedLights order).
std::vector<graph::TextureHandle> addShadowPasses(graph::RenderGraph& graph, FrameContext& frame, ShadowCache& cache);

}  // namespace dermis
