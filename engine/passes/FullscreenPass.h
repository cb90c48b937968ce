#pragma once
// The steps every full-screen pass's execute step shares: bind its render
// targets, set the viewport to cover the first, use its program, bind its
// input textures to units 0, 1, ... and draw one triangle that covers the
// viewport (shaders/fullscreen.vert).
//
//   runFullscreenPass(frame, resources, {{d.out}}, program, {d.depth, d.albedo});
//
// A pass that sets more state before drawing (a stencil test, blending,
// other texture units) calls beginFullscreenPass, then draws with
// frame.gl->drawFullscreenTriangle().

#include "graph/RenderGraph.h"
#include "render/FrameContext.h"

#include <utility>
#include <vector>

namespace dermis {

struct FullscreenTargets {
    FullscreenTargets(std::vector<graph::TextureHandle> colourTargets, graph::TextureHandle depthStencilTarget = {})
        : colour(std::move(colourTargets)), depthStencil(depthStencilTarget) {}
    std::vector<graph::TextureHandle> colour;  // draw buffers 0, 1, ...; an invalid handle ends the list
    graph::TextureHandle depthStencil;         // optional: a D24S8 target for a stencil test
};

// Binds the targets, the viewport and the program, and `inputs` to texture
// units 0, 1, ... in order; an invalid handle leaves its unit as it is.
void beginFullscreenPass(const FrameContext& frame, const graph::PassResources& resources,
                         const FullscreenTargets& targets, GLuint program,
                         const std::vector<graph::TextureHandle>& inputs);

// beginFullscreenPass, then the full-screen triangle.
void runFullscreenPass(const FrameContext& frame, const graph::PassResources& resources,
                       const FullscreenTargets& targets, GLuint program,
                       const std::vector<graph::TextureHandle>& inputs);

}  // namespace dermis
