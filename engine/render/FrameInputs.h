#pragma once
// What frame/FrameDeclaration.h's declareFrame imports into the graph: the
// backend textures that live outside the frame and the services the passes'
// execute steps draw with. render/FrameResources.h makes them; tests pass 0s.

#include "graph/TextureDesc.h"
#include "render/FrameContext.h"

#include <vector>

namespace dermis {

struct FrameInputs {
    graph::BackendTexture output = 0;  // RGBA8 for Aov::Final, RGBA32F otherwise, the frame's size
    graph::BackendTexture white = 0;   // 1x1 RGBA8
    graph::BackendTexture black = 0;   // 1x1 RGBA8
    std::vector<graph::BackendTexture> shadowMaps;  // one per FramePlan::shadows; missing ones import as 0
    // What the passes' execute steps draw with; null when the graph is only
    // compiled. It and the plan must outlive the graph's execution.
    const FrameServices* services = nullptr;
};

}  // namespace dermis
