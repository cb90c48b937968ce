#pragma once
// GPU skinning: one compute pass per animated character
// (CharacterPlacement::animated), declared before every pass that draws
// meshes, writing the character's pose into the vertex buffer the shadow,
// G-buffer and texture-space passes all draw from, so the mesh is skinned
// once per frame however many passes draw it. Skipped when the buffer holds
// this pose already (plan/PoseCache.h), and when no pass draws the
// character this frame (off screen and in no redrawn shadow map). The manual
// is shaders/skinning.comp.

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

namespace dermis {

void addSkinningPasses(graph::RenderGraph& graph, const FrameContext& frame);

}  // namespace dermis
