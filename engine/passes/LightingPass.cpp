#include "passes/LightingPass.h"

namespace dermis {
namespace {
struct LightingData {
    GBuffer gbuffer;
    std::vector<graph::TextureHandle> shadowMaps;
    graph::TextureHandle ambientOcclusion;
    graph::TextureHandle leanCross;
    Lighting out;
};
}  // namespace

void bindShadowMaps(const FrameContext& frame, const graph::PassResources& resources,
                    const std::vector<graph::TextureHandle>& shadowMaps) {
    for (size_t slot = 0; slot < DERMIS_MAX_SHADOWED_LIGHTS; ++slot) {
        const GLuint map = slot < shadowMaps.size() ? resources.texture(shadowMaps[slot]) : frame.whiteTexture;
        glBindTextureUnit(static_cast<GLuint>(4 + slot), map);
    }
}

Lighting addLightingPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle ambientOcclusion,
                         bool shadowVisibility) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
    return graph
        .addPass<LightingData>(
            "lighting",
            [&](graph::PassBuilder& builder, LightingData& d) {
                d.gbuffer.depthStencil = builder.read(gbuffer.depthStencil);
                d.gbuffer.albedo = builder.read(gbuffer.albedo);
                d.gbuffer.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.ambientOcclusion = builder.read(ambientOcclusion);
                if (gbuffer.hasLean()) d.leanCross = builder.read(gbuffer.leanCross);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                d.out.irradiance = builder.create("irradiance", {w, h, graph::TextureFormat::Rgba16F});
                d.out.specular = builder.create("specular", {w, h, graph::TextureFormat::Rgba16F});
                if (shadowVisibility) d.out.visibility = builder.create("shadow visibility", {w, h, graph::TextureFormat::Rgba8});
            },
            [&frame](const graph::PassResources& resources, const LightingData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out.irradiance);
                attachments.colour[1] = resources.texture(d.out.specular);
                if (d.out.visibility.isValid()) attachments.colour[2] = resources.texture(d.out.visibility);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                const bool lean = d.leanCross.isValid();
                glUseProgram(lean ? frame.programs->lightingLean.get() : frame.programs->lighting.get());
                if (lean) glBindTextureUnit(8, resources.texture(d.leanCross));
                glBindTextureUnit(0, resources.texture(d.gbuffer.depthStencil));
                glBindTextureUnit(1, resources.texture(d.gbuffer.albedo));
                glBindTextureUnit(2, resources.texture(d.gbuffer.normalMaterial));
                glBindTextureUnit(3, resources.texture(d.ambientOcclusion));
                bindShadowMaps(frame, resources, d.shadowMaps);
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
