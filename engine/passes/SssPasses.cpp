#include "passes/SssPasses.h"

#include "render/SssVariant.h"
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
    const SssSettings& settings = frame.scene->settings.sss;
    gpu::SssBlurBlock block{};
    const int taps = writeKernelTaps(kernel, block.kernel);
    // The discrete kernel's own variance is a little more than 1 sigma^2, so
    // its offsets are scaled for the step to blur by exactly stepVarianceMm2.
    const float sigmaMm = std::sqrt(step.stepVarianceMm2 / kernelVarianceSigma2(kernel));
    block.step = glm::vec4(horizontal ? 1.0f : 0.0f, horizontal ? 0.0f : 1.0f, sigmaMm, float(taps));
    block.edges = glm::vec4(float(sssBlurEdges(settings)), settings.bilateralDepthMm,
                            settings.controlDepthScalePerMm, float(slot));
    return block;
}

}  // namespace

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
        glScissor(0, 0, frame.width, frame.height);
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

SssChain addSssChain(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                     graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
    const graph::TextureDesc colourDesc{w, h, graph::TextureFormat::Rgba16F};
    const bool anyVisible = frame.sss.anyVisible();
    assert(extras.empty() || extras.size() == kLeanSssTargets);
    const bool packed = !extras.empty();  // the chain carries colour and moments as halves (SssBlur.glsl)
    const graph::TextureDesc chainDesc{w, h, packed ? graph::TextureFormat::Rgba32UI : graph::TextureFormat::Rgba16F};
    const Programs& programs = *frame.programs;
    const GLuint initProgram = packed ? programs.sssInitLean.get() : programs.sssInit.get();
    const GLuint blurProgram = packed ? programs.sssBlurLean.get() : programs.sssBlur.get();

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
            if (packed) d.chain = builder.create("sss chain", chainDesc);
            builder.skipIf(!frame.scene->settings.sss.enabled, "SSS disabled");
            builder.skipIf(!anyVisible, "no SSS pixel on screen");
        },
        [&frame, initProgram](const graph::PassResources& resources, const InitData& d) {
            gl::Attachments attachments;
            attachments.colour[0] = resources.texture(d.accumulated);
            if (d.chain.isValid()) {
                attachments.colour[1] = resources.texture(d.extrasAccumulated[0]);
                attachments.colour[2] = resources.texture(d.chain);
            }
            frame.framebuffers->bind(attachments);
            frame.setViewport(frame.width, frame.height);
            glUseProgram(initProgram);
            glBindTextureUnit(0, resources.texture(d.irradiance));
            glBindTextureUnit(1, resources.texture(d.depthKey));
            if (d.chain.isValid()) glBindTextureUnit(2, resources.texture(d.extras[0]));
            frame.drawFullscreenTriangle();
        });
    SssChain chain{init.accumulated, init.extrasAccumulated};
    const graph::TextureHandle chainStart = packed ? init.chain : irradiance;

    auto kernel = makeGaussianKernel(frame.scene->settings.sss.taps);
    if (!kernel.ok()) return chain;  // the scene loader validates taps; nothing to blur with
    const BlurKernel taps = *kernel;  // copied into each pass: it outlives this function

    for (const SssSlotPlan& slot : frame.sss.slots) {
        graph::TextureHandle current = chainStart;
        const std::string prefix = "sss " + slot.profile->name() + " g";
        for (const SssGaussianStep& step : slot.steps) {
            const std::string name = prefix + std::to_string(step.gaussian);
            char why[96];
            std::snprintf(why, sizeof why, slot.visible ? "%.2f px wide at the nearest SSS pixel (< %g px)"
                                                        : "no pixel of this profile on screen",
                          double(step.widthPxAtNearest), double(frame.scene->settings.sss.minWidthPx));
            const BlurData& horizontal = graph.addPass<BlurData>(
                name + " h",
                [&](graph::PassBuilder& builder, BlurData& d) {
                    d.colour = builder.read(current);
                    d.depthKey = builder.read(gbuffer.depthKey);
                    d.stencil = builder.read(gbuffer.depthStencil);
                    d.out = builder.create(name + " h", chainDesc);
                    builder.skipIf(!frame.scene->settings.sss.enabled, "SSS disabled");
                    builder.skipIf(step.skipped, why);
                },
                [&frame, taps, step, blurProgram, slotIndex = slot.slot, scissor = slot.scissor](
                    const graph::PassResources& resources, const BlurData& d) {
                    gl::Attachments attachments;
                    attachments.colour[0] = resources.texture(d.out);
                    attachments.depth = resources.texture(d.stencil);
                    attachments.depthHasStencil = true;
                    frame.framebuffers->bind(attachments);
                    frame.setViewport(frame.width, frame.height);
                    const gpu::SssBlurBlock block = blurBlock(frame, taps, step, slotIndex, true);
                    frame.uploadPassBlock(&block, sizeof block);
                    glUseProgram(blurProgram);
                    glBindTextureUnit(0, resources.texture(d.colour));
                    glBindTextureUnit(1, resources.texture(d.depthKey));
                    const ScopedSssState state(frame, scissor, slotIndex);
                    frame.drawFullscreenTriangle();
                });
            const BlurData& vertical = graph.addPass<BlurData>(
                name + " v",
                [&](graph::PassBuilder& builder, BlurData& d) {
                    d.colour = builder.read(horizontal.out);
                    d.depthKey = builder.read(gbuffer.depthKey);
                    d.stencil = builder.read(gbuffer.depthStencil);
                    d.accumulatedIn = builder.read(chain.diffuse);
                    d.out = builder.create(name + " v", chainDesc);
                    d.accumulatedOut = builder.write(chain.diffuse);
                    builder.passThrough(d.out, current);
                    for (graph::TextureHandle accumulated : chain.extras) {
                        d.extrasAccumulatedIn.push_back(builder.read(accumulated));
                        d.extrasAccumulatedOut.push_back(builder.write(accumulated));
                    }
                },
                [&frame, taps, step, blurProgram, slotIndex = slot.slot, scissor = slot.scissor](
                    const graph::PassResources& resources, const BlurData& d) {
                    gl::Attachments attachments;
                    attachments.colour[0] = resources.texture(d.out);
                    attachments.colour[1] = resources.texture(d.accumulatedOut);
                    for (size_t k = 0; k < d.extrasAccumulatedOut.size(); ++k) {
                        attachments.colour[2 + k] = resources.texture(d.extrasAccumulatedOut[k]);
                    }
                    attachments.depth = resources.texture(d.stencil);
                    attachments.depthHasStencil = true;
                    frame.framebuffers->bind(attachments);
                    frame.setViewport(frame.width, frame.height);
                    const gpu::SssBlurBlock block = blurBlock(frame, taps, step, slotIndex, false);
                    frame.uploadPassBlock(&block, sizeof block);
                    glUseProgram(blurProgram);
                    glBindTextureUnit(0, resources.texture(d.colour));
                    glBindTextureUnit(1, resources.texture(d.depthKey));
                    const ScopedSssState state(frame, scissor, slotIndex);
                    // Irradiance: += w_i (RGB) x value; its alpha and the moments: += mean(w_i) x value (SssVariant.h).
                    glEnablei(GL_BLEND, 1);
                    glBlendFuncSeparatei(1, GL_CONSTANT_COLOR, GL_ONE, GL_CONSTANT_ALPHA, GL_ONE);
                    for (size_t k = 0; k < d.extrasAccumulatedOut.size(); ++k) {
                        glEnablei(GL_BLEND, static_cast<GLuint>(2 + k));
                        glBlendFunci(static_cast<GLuint>(2 + k), GL_CONSTANT_ALPHA, GL_ONE);
                    }
                    glBlendColor(step.weight.r, step.weight.g, step.weight.b, sssMomentWeight(step.weight));
                    frame.drawFullscreenTriangle();
                    for (size_t k = 0; k <= d.extrasAccumulatedOut.size(); ++k) glDisablei(GL_BLEND, static_cast<GLuint>(1 + k));
                });
            current = vertical.out;
            chain.diffuse = vertical.accumulatedOut;
            chain.extras = vertical.extrasAccumulatedOut;
        }
    }
    return chain;
}

graph::TextureHandle addSssPasses(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                  graph::TextureHandle irradiance) {
    return addSssChain(graph, frame, gbuffer, irradiance, {}).diffuse;
}

}  // namespace dermis
