#include "passes/FullscreenPass.h"

#include "plan/ScreenFootprint.h"
#include "plan/ScreenRegions.h"

#include <cassert>

namespace dermis {

void beginFullscreenPass(const FrameContext& frame, const graph::PassResources& resources,
                         const FullscreenTargets& targets, GLuint program,
                         const std::vector<graph::TextureHandle>& inputs) {
    assert(!targets.colour.empty() && targets.colour.size() <= gl::kMaxColourAttachments);
    gl::Attachments attachments;
    for (size_t i = 0; i < targets.colour.size() && targets.colour[i].isValid(); ++i) {
        attachments.colour[i] = resources.texture(targets.colour[i]);
    }
    if (targets.depthStencil.isValid()) {
        attachments.depth = resources.texture(targets.depthStencil);
        attachments.depthHasStencil = true;
    }
    frame.gl->framebuffers->bind(attachments);
    const graph::TextureDesc& size = resources.desc(targets.colour.front());
    frame.gl->setViewport(static_cast<int>(size.width), static_cast<int>(size.height));
    glUseProgram(program);
    for (size_t unit = 0; unit < inputs.size(); ++unit) {
        if (inputs[unit].isValid()) glBindTextureUnit(static_cast<GLuint>(unit), resources.texture(inputs[unit]));
    }
}

std::vector<glm::ivec4> characterRegions(const FramePlan& plan, const std::function<bool(size_t)>& include) {
    std::vector<glm::ivec4> rects;
    for (size_t index = 0; index < plan.characters.size(); ++index) {
        const CharacterPlacement& character = plan.characters[index];
        if (!character.visible || (include && !include(index))) continue;
        const ScreenFootprint footprint = screenFootprint(character.worldBounds, plan.view);
        if (footprint.visible) rects.push_back(footprint.scissor);
    }
    return disjointCover(rects);
}

void drawCharacterPixels(const FrameContext& frame, const std::vector<glm::ivec4>& regions, size_t drawBuffers,
                         const glm::vec4& background) {
    for (size_t i = 0; i < drawBuffers; ++i) glClearBufferfv(GL_COLOR, static_cast<GLint>(i), &background.x);
    if (!regions.empty()) frame.gl->drawRegions(regions);
}

void runFullscreenPass(const FrameContext& frame, const graph::PassResources& resources,
                       const FullscreenTargets& targets, GLuint program,
                       const std::vector<graph::TextureHandle>& inputs) {
    beginFullscreenPass(frame, resources, targets, program, inputs);
    frame.gl->drawFullscreenTriangle();
}

}  // namespace dermis
