// The disk technique (shaders/include/DiskSss.glsl is its manual): one pass per
// profile slot whose choice is SssTechnique::Disk, `sss <profile> disk`, which
// samples the slot's profile on a disk around each pixel (Christensen & Burley
// 2015 §5, as Unity HDRP does, Golubev 2018) and overwrites the accumulations
// on that slot's pixels.
#include "passes/SssPasses.h"

#include "passes/FullscreenPass.h"
#include "plan/SssVariant.h"
#include "sss/DiskKernel.h"

#include <cmath>
#include <string>

namespace dermis {
namespace {

static_assert(sizeof(gpu::DiskSssBlock) <= kMaxPassBlockBytes, "the disk's block must fit the per-pass buffer");

struct DiskData {
    graph::TextureHandle colour, depthKey, stencil, hiddenSide, accumulatedIn, accumulatedOut;
    std::vector<graph::TextureHandle> extrasAccumulatedIn, extrasAccumulatedOut;
};

gpu::DiskSssBlock diskBlock(const SssSettings& settings, const DiskKernel& kernel, int slot) {
    gpu::DiskSssBlock block{};
    float largestRadiusMm = 0.0f;
    for (int k = 0; k < kernel.count; ++k) {
        const DiskSample& sample = kernel.samples[size_t(k)];
        block.samples[k] = glm::vec4(sample.radiusMm * std::cos(sample.angleRad), sample.radiusMm * std::sin(sample.angleRad),
                                     sample.radiusMm, sssMomentWeight(sample.weight));
        block.weights[k] = glm::vec4(sample.weight, 0.0f);
        largestRadiusMm = std::fmax(largestRadiusMm, sample.radiusMm);
    }
    block.sampleCount = kernel.count;
    block.largestRadiusMm = largestRadiusMm;
    block.edges = sssEdgeParams(settings, slot);
    return block;
}

}  // namespace

SssChain addDiskSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer, const SssStart& start,
                    SssChain chain) {
    const SssSettings& settings = frame.plan.scene->settings.sss;
    for (const SssSlotPlan& slot : frame.plan.sss.slots) {
        if (slot.choice.technique != SssTechnique::Disk) continue;
        Result<DiskKernel> kernel = makeDiskKernel(*slot.profile, slot.choice.diskSamples, slot.widthScale);
        const gpu::DiskSssBlock block = kernel.ok() ? diskBlock(settings, *kernel, slot.slot) : gpu::DiskSssBlock{};
        const DiskData& disk = graph.addPass<DiskData>(
            "sss " + slot.name + " disk",
            [&](graph::PassBuilder& builder, DiskData& d) {
                d.colour = builder.read(start.chain);
                d.depthKey = builder.read(gbuffer.depthKey);
                d.stencil = builder.read(gbuffer.depthStencil);
                d.hiddenSide = builder.read(start.hiddenSide);
                // Read as well as written: the pass overwrites this slot's pixels only.
                d.accumulatedIn = builder.read(chain.diffuse);
                d.accumulatedOut = builder.write(chain.diffuse);
                for (graph::TextureHandle accumulated : chain.extras) {
                    d.extrasAccumulatedIn.push_back(builder.read(accumulated));
                    d.extrasAccumulatedOut.push_back(builder.write(accumulated));
                }
                builder.skipIf(!settings.enabled, "SSS disabled");
                builder.skipIf(!slot.visible, "no pixel of this profile on screen");
                builder.skipIf(!kernel.ok(), kernel.ok() ? "" : kernel.error().what);
            },
            [frame, block, scissor = slot.scissor, regions = slot.regions, slotId = slot.slot,
             packed = start.packed](const graph::PassResources& resources, const DiskData& d) {
                std::vector<graph::TextureHandle> targets = {d.accumulatedOut};
                targets.insert(targets.end(), d.extrasAccumulatedOut.begin(), d.extrasAccumulatedOut.end());
                const Programs& programs = *frame.gl->programs;
                beginFullscreenPass(frame, resources, {targets, d.stencil},
                                    packed ? programs.sssDiskLean.get() : programs.sssDisk.get(), {d.colour, d.depthKey});
                glBindTextureUnit(DERMIS_UNIT_HIDDEN_SIDE, resources.texture(d.hiddenSide));
                frame.gl->uploadPassBlock(&block, sizeof block);
                const ScopedSssState state(frame, scissor, slotId);
                frame.gl->drawRegions(regions);
            });
        chain.diffuse = disk.accumulatedOut;
        chain.extras = disk.extrasAccumulatedOut;
    }
    return chain;
}

}  // namespace dermis
