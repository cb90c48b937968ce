#include "passes/SsaoPass.h"

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
    const SsaoSettings& ssao = frame.scene->settings.ssao;
    if (!ssao.enabled) return "SSAO is disabled (settings.ssao.enabled = false)";
    if (!(ssao.strength > 0.0f)) return "SSAO strength is 0";
    if (frame.scene->characters.empty()) return "no characters";
    return {};
}

void uploadSsaoBlock(const FrameContext& frame) {
    const gpu::SsaoBlock block = makeSsaoBlock(frame.scene->settings.ssao);
    glBindBufferBase(GL_UNIFORM_BUFFER, DERMIS_BINDING_PASS, frame.passUniforms);
    frame.uploadPassBlock(&block, sizeof block);
}

}  // namespace

gpu::SsaoBlock makeSsaoBlock(const SsaoSettings& settings) {
    gpu::SsaoBlock block{};
    block.kernel = glm::vec4(settings.radiusM, float(settings.samples), kSsaoBiasFractionOfRadius,
                             kSsaoRangeFadeEndRadii);
    block.blur = glm::vec4(float(kSsaoBlurHalfWidthPx), kSsaoBlurDepthTolerance, 0.0f, 0.0f);
    return block;
}

graph::TextureHandle addSsaoPasses(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                   graph::TextureHandle white) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
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
                [&frame](const graph::PassResources& resources, const SsaoData& d) {
                    gl::Attachments attachments;
                    attachments.colour[0] = resources.texture(d.ao);
                    frame.framebuffers->bind(attachments);
                    frame.setViewport(frame.width, frame.height);
                    uploadSsaoBlock(frame);
                    glUseProgram(frame.programs->ssao.get());
                    glBindTextureUnit(0, resources.texture(d.depth));
                    glBindTextureUnit(1, resources.texture(d.normalMaterial));
                    glBindTextureUnit(2, resources.texture(d.albedo));
                    frame.drawFullscreenTriangle();
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
                builder.skipIf(!frame.scene->settings.ssao.blur, "SSAO blur is off (settings.ssao.blur = false)");
            },
            [&frame](const graph::PassResources& resources, const SsaoBlurData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.ao);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                uploadSsaoBlock(frame);
                glUseProgram(frame.programs->ssaoBlur.get());
                glBindTextureUnit(0, resources.texture(d.rawAo));
                glBindTextureUnit(1, resources.texture(d.depthKey));
                frame.drawFullscreenTriangle();
            })
        .ao;
}

}  // namespace dermis
