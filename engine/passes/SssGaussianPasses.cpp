// The d'Eon chain (technique "gaussians"; shaders/include/SssBlur.glsl is its
// manual): per profile slot, one separable blur pair per Gaussian, each
// vertical pass adding w_i x its result into the accumulations.
#include "passes/SssPasses.h"

#include "passes/FullscreenPass.h"
#include "plan/SssVariant.h"
#include "sss/BlurKernel.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace dermis {
namespace {

struct BlurData {
    graph::TextureHandle colour, depthKey, stencil, hiddenSide, accumulatedIn, out, accumulatedOut;
    std::vector<graph::TextureHandle> extrasAccumulatedIn, extrasAccumulatedOut;
};

gpu::SssBlurBlock blurBlock(const FrameContext& frame, const BlurKernel& kernel, const SssGaussianStep& step,
                            int slot, bool horizontal) {
    const SssSettings& settings = frame.plan.scene->settings.sss;
    gpu::SssBlurBlock block{};
    const int taps = writeKernelTaps(kernel, block.kernel);
    // The shader matches the discrete kernel's variance to this width itself,
    // per pixel (SssBlur.glsl, "SAMPLING AND WEIGHTS").
    const float sigmaMm = std::sqrt(step.stepVarianceMm2);
    block.direction = horizontal ? glm::vec2(1.0f, 0.0f) : glm::vec2(0.0f, 1.0f);
    block.sigmaMm = sigmaMm;
    block.taps = taps;
    block.edges = sssEdgeParams(settings, slot);
    block.readsIrradiance = step.readsIrradiance ? 1 : 0;
    return block;
}

// One direction of one Gaussian step of one profile slot (Jimenez et al.
// 2009: a separable blur, horizontal then vertical). The vertical pass also
// adds w_i x its result into the accumulations by blending (d'Eon & Luebke
// 2007 §16.4.3) and hands readers `previous` when it cannot run; the
// horizontal pass carries the step's predicate, and a culled horizontal
// pass culls its vertical one as a missing input.
struct BlurStep {
    std::string name;       // "sss <profile> g<i>"
    const SssSlotPlan* slot = nullptr;
    SssGaussianStep step;
    bool horizontal = true;
    bool packed = false;     // reads the chain of irradiance and LEAN moments (SssBlur.glsl, "PACKING")
    bool packedOut = false;  // writes it: false in the last step that carries the moments
    // The moments' (and the colour alpha's) accumulation weight of a vertical pass:
    // the step's own, the rest of the chain's in the last step that carries the
    // moments, 0 after it (SssBlur.glsl, "WHERE THE MOMENTS STOP").
    float momentWeight = 0.0f;
    std::string skipReason;
    graph::TextureHandle hiddenSide;  // include/ThinEdges.glsl
};

const BlurData& addBlurPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                            const BlurStep& blur, graph::TextureHandle in, graph::TextureHandle previous,
                            SssChain& chain, const graph::TextureDesc& chainDesc) {
    const std::string passName = blur.name + (blur.horizontal ? " h" : " v");
    return graph.addPass<BlurData>(
        passName,
        [&](graph::PassBuilder& builder, BlurData& d) {
            d.colour = builder.read(in);
            d.depthKey = builder.read(gbuffer.depthKey);
            d.stencil = builder.read(gbuffer.depthStencil);
            d.hiddenSide = builder.read(blur.hiddenSide);
            if (blur.horizontal) {
                d.out = builder.create(passName, chainDesc);
                builder.skipIf(!frame.plan.scene->settings.sss.enabled, "SSS disabled");
                builder.skipIf(blur.step.skipped, blur.skipReason);
                return;
            }
            d.accumulatedIn = builder.read(chain.diffuse);
            d.out = builder.create(passName, chainDesc);
            d.accumulatedOut = builder.write(chain.diffuse);
            builder.passThrough(d.out, previous);
            if (!blur.packed) return;
            for (graph::TextureHandle accumulated : chain.extras) {
                d.extrasAccumulatedIn.push_back(builder.read(accumulated));
                d.extrasAccumulatedOut.push_back(builder.write(accumulated));
            }
        },
        [frame, step = blur.step, slot = blur.slot->slot, kernel = blur.slot->gaussianKernel, scissor = blur.slot->scissor, regions = blur.slot->regions,
         horizontal = blur.horizontal, packed = blur.packed, packedOut = blur.packedOut,
         momentWeight = blur.momentWeight](const graph::PassResources& resources, const BlurData& d) {
            std::vector<graph::TextureHandle> targets = {d.out, d.accumulatedOut};
            targets.insert(targets.end(), d.extrasAccumulatedOut.begin(), d.extrasAccumulatedOut.end());
            const Programs& programs = *frame.gl->programs;
            const gl::Program& program = !packed ? programs.sssBlur : packedOut ? programs.sssBlurLean : programs.sssBlurLeanLast;
            beginFullscreenPass(frame, resources, {targets, d.stencil}, program.get(), {d.colour, d.depthKey});
            glBindTextureUnit(DERMIS_UNIT_HIDDEN_SIDE, resources.texture(d.hiddenSide));
            const gpu::SssBlurBlock block = blurBlock(frame, kernel, step, slot, horizontal);
            frame.gl->uploadPassBlock(&block, sizeof block);
            const ScopedSssState state(frame, scissor, slot);
            if (horizontal) {
                frame.gl->drawRegions(regions);
                return;
            }
            // Irradiance: += w_i (RGB) x value; its alpha and the moments: += mean(w_i) x value (SssVariant.h).
            glEnablei(GL_BLEND, 1);
            glBlendFuncSeparatei(1, GL_CONSTANT_COLOR, GL_ONE, GL_CONSTANT_ALPHA, GL_ONE);
            for (size_t k = 0; k < d.extrasAccumulatedOut.size(); ++k) {
                glEnablei(GL_BLEND, static_cast<GLuint>(2 + k));
                glBlendFunci(static_cast<GLuint>(2 + k), GL_CONSTANT_ALPHA, GL_ONE);
            }
            glBlendColor(step.weight.r, step.weight.g, step.weight.b, momentWeight);
            frame.gl->drawRegions(regions);
            for (size_t k = 0; k <= d.extrasAccumulatedOut.size(); ++k) glDisablei(GL_BLEND, static_cast<GLuint>(1 + k));
        });
}

}  // namespace

SssChain addSssGaussianChain(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                             const SssStart& start, SssChain chain) {
    const graph::TextureHandle chainStart = start.chain;
    // Past the moments' last step the chain is the colour alone, as without LEAN.
    const graph::TextureDesc plainDesc{start.chainDesc.width, start.chainDesc.height, graph::TextureFormat::Rgba16F};

    for (const SssSlotPlan& slot : frame.plan.sss.slots) {
        if (slot.choice.technique != SssTechnique::Gaussians) continue;
        const SssMomentCut cut = sssMomentCut(slot.steps, frame.plan.scene->settings.sss.leanMomentWidthMm);
        graph::TextureHandle current = chainStart;
        for (size_t i = 0; i < slot.steps.size(); ++i) {
            const SssGaussianStep& step = slot.steps[i];
            BlurStep blur;
            blur.name = "sss " + slot.name + " g" + std::to_string(step.gaussian);
            blur.slot = &slot;
            blur.step = step;
            blur.hiddenSide = start.hiddenSide;
            blur.packed = start.packed && i <= cut.lastStep;
            blur.packedOut = blur.packed;  // the horizontal pass hands the vertical one the moments
            blur.momentWeight = !start.packed        ? sssMomentWeight(step.weight)
                                : i < cut.lastStep   ? sssMomentWeight(step.weight)
                                : i == cut.lastStep ? cut.weight
                                                     : 0.0f;
            char why[96];
            std::snprintf(why, sizeof why, slot.visible ? "%.2f px wide at the nearest SSS pixel (< %g px)"
                                                        : "no pixel of this profile on screen",
                          double(step.widthPxAtNearest), double(frame.plan.scene->settings.sss.minWidthPx));
            blur.skipReason = why;
            const BlurData& horizontal = addBlurPass(graph, frame, gbuffer, blur, current, {}, chain,
                                                     blur.packed ? start.chainDesc : plainDesc);
            blur.horizontal = false;
            blur.packedOut = blur.packed && i < cut.lastStep;
            const BlurData& vertical = addBlurPass(graph, frame, gbuffer, blur, horizontal.out, current, chain,
                                                   blur.packedOut ? start.chainDesc : plainDesc);
            current = vertical.out;
            chain.diffuse = vertical.accumulatedOut;
            if (blur.packed) chain.extras = vertical.extrasAccumulatedOut;
        }
    }
    return chain;
}

}  // namespace dermis
