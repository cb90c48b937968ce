// Separable SSS (Jimenez et al. 2015): per slot whose technique is separable,
//
//   sss <profile> separable h   chain start -> temporary, the 1-D kernel along x
//   sss <profile> separable v   temporary -> accumulation(s), along y, overwriting sss init's value
//
// under the slot's stencil, scissor and regions. The kernel is computed here
// on the CPU from the slot's profile (sss/SeparableKernel.h); the shader's
// manual is shaders/include/SeparableSss.glsl.
#include "passes/SssPasses.h"

#include "passes/FullscreenPass.h"
#include "sss/SeparableKernel.h"

#include <string>

namespace dermis {
namespace {

struct SeparableData {
    graph::TextureHandle chain, depthKey, stencil, hiddenSide, out;
    std::vector<graph::TextureHandle> accumulatedIn, accumulatedOut;  // vertical: colour, then the extras
};

// The slot's kernel, offsets times its width scale (the marginal of a profile
// scaled by s is K(x / s) / s, so the cell integrals stay those of K).
gpu::SeparableSssBlock separableBlock(const FrameContext& frame, const SssSlotPlan& slot, const SeparableKernel& kernel,
                                      bool horizontal) {
    const SssSettings& settings = frame.plan.scene->settings.sss;
    gpu::SeparableSssBlock block{};
    for (int i = 0; i < kernel.count; ++i) {
        const SeparableTap& tap = kernel.taps[size_t(i)];
        block.taps[i] = glm::vec4(tap.weight, tap.offsetMm * slot.widthScale);
    }
    block.direction = horizontal ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
    block.tapCount = kernel.count;
    block.isVertical = horizontal ? 0 : 1;
    block.edges = sssEdgeParams(settings, slot.slot);
    return block;
}

const SeparableData& addSeparablePass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                      const SssSlotPlan& slot, const gpu::SeparableSssBlock& block,
                                      const std::string& skipReason, const SssStart& start, graph::TextureHandle in,
                                      const SssChain& chain) {
    const bool horizontal = block.isVertical == 0;
    const std::string passName = "sss " + slot.name + " separable" + (horizontal ? " h" : " v");
    return graph.addPass<SeparableData>(
        passName,
        [&](graph::PassBuilder& builder, SeparableData& d) {
            d.chain = builder.read(in);
            d.depthKey = builder.read(gbuffer.depthKey);
            d.stencil = builder.read(gbuffer.depthStencil);
            d.hiddenSide = builder.read(start.hiddenSide);
            if (horizontal) {
                d.out = builder.create(passName, start.chainDesc);
                builder.skipIf(!frame.plan.scene->settings.sss.enabled, "SSS disabled");
                builder.skipIf(!skipReason.empty(), skipReason);
                return;
            }
            // Read as well as written: the slot's pixels are overwritten, every other pixel keeps its value.
            std::vector<graph::TextureHandle> accumulated = {chain.diffuse};
            accumulated.insert(accumulated.end(), chain.extras.begin(), chain.extras.end());
            for (graph::TextureHandle target : accumulated) {
                d.accumulatedIn.push_back(builder.read(target));
                d.accumulatedOut.push_back(builder.write(target));
            }
        },
        [frame, block, horizontal, packed = start.packed, scissor = slot.scissor, slotIndex = slot.slot,
         regions = slot.regions](const graph::PassResources& resources, const SeparableData& d) {
            const Programs& programs = *frame.gl->programs;
            const gl::Program& program = horizontal ? (packed ? programs.sssSeparableLeanH : programs.sssSeparableH)
                                                    : (packed ? programs.sssSeparableLeanV : programs.sssSeparableV);
            const std::vector<graph::TextureHandle> targets = horizontal ? std::vector<graph::TextureHandle>{d.out}
                                                                         : d.accumulatedOut;
            beginFullscreenPass(frame, resources, {targets, d.stencil}, program.get(), {d.chain, d.depthKey});
            glBindTextureUnit(DERMIS_UNIT_HIDDEN_SIDE, resources.texture(d.hiddenSide));
            frame.gl->uploadPassBlock(&block, sizeof block);
            const ScopedSssState state(frame, scissor, slotIndex);
            frame.gl->drawRegions(regions);
        });
}

}  // namespace

SssChain addSeparableSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer, const SssStart& start,
                         SssChain chain) {
    for (const SssSlotPlan& slot : frame.plan.sss.slots) {
        if (slot.choice.technique != SssTechnique::Separable) continue;
        Result<SeparableKernel> kernel = makeSeparableKernel(*slot.profile, slot.choice.separableSamples);
        std::string skipReason;
        if (!slot.visible) skipReason = "no pixel of this profile on screen";
        if (!kernel.ok()) skipReason = kernel.error().message();
        const SeparableKernel taps = kernel.ok() ? kernel.value() : SeparableKernel{};
        const SeparableData& horizontal = addSeparablePass(graph, frame, gbuffer, slot, separableBlock(frame, slot, taps, true),
                                                           skipReason, start, start.chain, chain);
        const SeparableData& vertical = addSeparablePass(graph, frame, gbuffer, slot, separableBlock(frame, slot, taps, false),
                                                         skipReason, start, horizontal.out, chain);
        chain.diffuse = vertical.accumulatedOut[0];
        chain.extras.assign(vertical.accumulatedOut.begin() + 1, vertical.accumulatedOut.end());
    }
    return chain;
}

}  // namespace dermis
