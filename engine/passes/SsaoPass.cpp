#include "passes/SsaoPass.h"

#include "passes/FullscreenPass.h"

#include <string>

namespace dermis {
namespace {

struct SsaoData {
    graph::TextureHandle depth;
    graph::TextureHandle normalMaterial;
    graph::TextureHandle albedo;
    graph::TextureHandle ao;
};

struct SsaoBlurData {
    graph::TextureHandle rawAo;
    graph::TextureHandle depthKey;
    graph::TextureHandle ao;
};

// Why SSAO has nothing to do this frame; empty when it runs.
std::string ssaoSkipReason(const FrameContext& frame) {
    const SsaoSettings& ssao = frame.plan.scene->settings.ssao;
    if (!ssao.enabled) return "SSAO is disabled (settings.ssao.enabled = false)";
    if (!(ssao.strength > 0.0f)) return "SSAO strength is 0";
    if (frame.plan.scene->characters.empty()) return "no characters";
    return {};
}

void uploadSsaoBlock(const FrameContext& frame) {
    const gpu::SsaoBlock block = makeSsaoBlock(frame.plan.scene->settings.ssao);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PASS, frame.gl->passUniforms);
    frame.gl->uploadPassBlock(&block, sizeof block);
}

}  // namespace

gpu::SsaoBlock makeSsaoBlock(const SsaoSettings& settings) {
    gpu::SsaoBlock block{};
    block.radiusM = settings.radiusM;
    block.samples = float(settings.samples);
    block.biasFraction = kSsaoBiasFractionOfRadius;
    block.fadeEndRadii = kSsaoRangeFadeEndRadii;
    block.blurHalfWidthPx = kSsaoBlurHalfWidthPx;
    block.blurDepthTolerance = kSsaoBlurDepthTolerance;
    return block;
}

graph::TextureHandle addSsaoPasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                   graph::TextureHandle white) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    const std::string skipReason = ssaoSkipReason(frame);

    const graph::TextureHandle rawAo =
        graph
            .addPass<SsaoData>(
                "ssao",
                [&](graph::PassBuilder& builder, SsaoData& d) {
                    d.depth = builder.read(gbuffer.depthStencil);
                    d.normalMaterial = builder.read(gbuffer.normalMaterial);
                    d.albedo = builder.read(gbuffer.albedo);
                    d.ao = builder.create("ao raw", {w, h, graph::TextureFormat::R8});
                    builder.passThrough(d.ao, white);
                    builder.skipIf(!skipReason.empty(), skipReason);
                },
                [frame](const graph::PassResources& resources, const SsaoData& d) {
                    uploadSsaoBlock(frame);
                    runFullscreenPass(frame, resources, {{d.ao}}, frame.gl->programs->ssao.get(),
                                      {d.depth, d.normalMaterial, d.albedo});
                })
            .ao;

    return graph
        .addPass<SsaoBlurData>(
            "ssao blur",
            [&](graph::PassBuilder& builder, SsaoBlurData& d) {
                d.rawAo = builder.read(rawAo);
                d.depthKey = builder.read(gbuffer.depthKey);
                d.ao = builder.create("ao", {w, h, graph::TextureFormat::R8});
                // Culled with "ssao" (below), this resolves through "ao raw" to white.
                builder.passThrough(d.ao, rawAo);
                builder.skipIf(!skipReason.empty(), skipReason);
                builder.skipIf(!frame.plan.scene->settings.ssao.blur, "SSAO blur is off (settings.ssao.blur = false)");
            },
            [frame](const graph::PassResources& resources, const SsaoBlurData& d) {
                uploadSsaoBlock(frame);
                runFullscreenPass(frame, resources, {{d.ao}}, frame.gl->programs->ssaoBlur.get(), {d.rawAo, d.depthKey});
            })
        .ao;
}

}  // namespace dermis
