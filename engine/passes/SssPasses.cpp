#include "passes/SssPasses.h"

#include "passes/FullscreenPass.h"
#include "plan/SssVariant.h"
#include "sss/BlurKernel.h"

#include <cassert>
#include <cstdio>
#include <string>

namespace dermis {
namespace {

struct InitData {
    graph::TextureHandle irradiance, depthKey, accumulated, chain;
    std::vector<graph::TextureHandle> extras, extrasAccumulated;
};
struct BlurData {
    graph::TextureHandle colour, depthKey, stencil, accumulatedIn, out, accumulatedOut;
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
            builder.skipIf(frame.plan.sss.onlyLightingScatters(), "every SSS slot on screen scatters in the lighting pass");
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
            blur.name = "sss " + slot.profile->name() + " g" + std::to_string(step.gaussian);
            blur.slot = &slot;
            blur.step = step;
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
