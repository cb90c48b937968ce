// What every screen-space technique shares: `sss init`, the slots' scissor
// and stencil state, the edge parameters. Each technique's own passes are in
// its file (passes/SssTechniquePasses.cpp lists them).
#include "passes/SssPasses.h"

#include "passes/FullscreenPass.h"
#include "plan/SssVariant.h"

#include <cassert>

namespace dermis {
namespace {

struct InitData {
    graph::TextureHandle irradiance, depthKey, accumulated, chain;
    std::vector<graph::TextureHandle> extras, extrasAccumulated;
};

}  // namespace

gpu::SssEdgeParams sssEdgeParams(const SssSettings& settings, int slot) {
    gpu::SssEdgeParams edges{};
    edges.mode = static_cast<int>(sssBlurEdges(settings));
    edges.bilateralDepthMm = settings.bilateralDepthMm;
    edges.controlScalePerMm = settings.controlDepthScalePerMm;
    edges.slot = slot;
    return edges;
}

glm::ivec4 sssScissor(const SssPlan& plan) {
    glm::ivec4 rect(0);
    for (const SssSlotPlan& slot : plan.slots) {
        if (!slot.visible) continue;
        if (rect.z == 0) {
            rect = slot.scissor;
            continue;
        }
        const glm::ivec2 lo = glm::min(glm::ivec2(rect), glm::ivec2(slot.scissor));
        const glm::ivec2 hi = glm::max(glm::ivec2(rect) + glm::ivec2(rect.z, rect.w),
                                       glm::ivec2(slot.scissor) + glm::ivec2(slot.scissor.z, slot.scissor.w));
        rect = glm::ivec4(lo, hi - lo);
    }
    return rect;
}

ScopedSssState::ScopedSssState(const FrameContext& frame, const glm::ivec4& scissor, int slot) {
    glEnable(GL_SCISSOR_TEST);
    if (scissor.z > 0 && scissor.w > 0) {
        glScissor(scissor.x, scissor.y, scissor.z, scissor.w);
    } else {
        glScissor(0, 0, frame.plan.width, frame.plan.height);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0x00);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    if (slot == kAnySssPixel) {
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
    } else {
        glStencilFunc(GL_EQUAL, slot, 0xFF);
    }
}

ScopedSssState::~ScopedSssState() {
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glDepthMask(GL_TRUE);
}

SssStart addSssInit(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                    graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    // Float: each of the six blended additions would otherwise round the sum to fp16 (up to
    // 0.024% each), 0.15% in the furnace at worst.
    const graph::TextureDesc colourDesc{w, h, graph::TextureFormat::Rgba32F};
    const bool anyVisible = frame.plan.sss.anyVisible();
    assert(extras.empty() || extras.size() == kLeanSssTargets);
    const bool packed = !extras.empty();  // the chain carries colour and moments as halves (SssBlur.glsl)
    SssStart start;
    start.chainDesc = {w, h, packed ? graph::TextureFormat::Rgba32UI : graph::TextureFormat::Rgba16F};

    const InitData& init = graph.addPass<InitData>(
        "sss init",
        [&](graph::PassBuilder& builder, InitData& d) {
            d.irradiance = builder.read(irradiance);
            d.depthKey = builder.read(gbuffer.depthKey);
            d.accumulated = builder.create("sss accumulated", colourDesc);
            builder.passThrough(d.accumulated, irradiance);
            for (graph::TextureHandle extra : extras) {
                d.extras.push_back(builder.read(extra));
                d.extrasAccumulated.push_back(
                    builder.create(graph.textureName(extra) + " accumulated", builder.desc(extra)));
                builder.passThrough(d.extrasAccumulated.back(), extra);
            }
            if (packed) d.chain = builder.create("sss chain", start.chainDesc);
            builder.skipIf(!frame.plan.scene->settings.sss.enabled, "SSS disabled");
            builder.skipIf(!anyVisible, "no SSS pixel on screen");
            // Their accumulation starts (and stays) at the irradiance itself.
            builder.skipIf(frame.plan.sss.chainIsIdentity(),
                           "no SSS slot on screen blurs (each scatters in the lighting pass or has every Gaussian "
                           "under min_width_px)");
        },
        [frame](const graph::PassResources& resources, const InitData& d) {
            const Programs& programs = *frame.gl->programs;
            if (!d.chain.isValid()) {
                runFullscreenPass(frame, resources, {{d.accumulated}}, programs.sssInit.get(), {d.irradiance, d.depthKey});
                return;
            }
            runFullscreenPass(frame, resources, {{d.accumulated, d.extrasAccumulated[0], d.chain}},
                              programs.sssInitLean.get(), {d.irradiance, d.depthKey, d.extras[0]});
        });
    start.accumulated = SssChain{init.accumulated, init.extrasAccumulated};
    start.chain = packed ? init.chain : irradiance;
    start.packed = packed;
    return start;
}

}  // namespace dermis
