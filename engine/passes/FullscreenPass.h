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

#include <functional>
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

// The pixels the frame's visible characters may cover: their screen
// footprints (plan/ScreenFootprint.h) as disjoint rectangles
// (plan/ScreenRegions.h); empty when no character is visible. A pass whose
// every background pixel takes one value clears its targets to it and draws
// these alone (drawCharacterPixels): on a CPU driver a shader's early return
// for the background still runs the rest of the shader under a mask.
// `include` (when given) picks the characters, by index.
std::vector<glm::ivec4> characterRegions(const FramePlan& plan, const std::function<bool(size_t)>& include = {});

// Clears every bound draw buffer to `background` and draws the character
// regions (nothing more where there are none). After beginFullscreenPass.
void drawCharacterPixels(const FrameContext& frame, const std::vector<glm::ivec4>& regions, size_t drawBuffers,
                         const glm::vec4& background);

// beginFullscreenPass, then the full-screen triangle.
void runFullscreenPass(const FrameContext& frame, const graph::PassResources& resources,
                       const FullscreenTargets& targets, GLuint program,
                       const std::vector<graph::TextureHandle>& inputs);

}  // namespace dermis
