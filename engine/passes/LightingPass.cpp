#include "passes/LightingPass.h"

namespace dermis {
namespace {
struct LightingData {
    GBuffer gbuffer;
    std::vector<graph::TextureHandle> shadowMaps;
    Lighting out;
};
}  // namespace

Lighting addLightingPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
    return graph
        .addPass<LightingData>(
            "lighting",
            [&](graph::PassBuilder& builder, LightingData& d) {
                d.gbuffer.depthStencil = builder.read(gbuffer.depthStencil);
                d.gbuffer.albedo = builder.read(gbuffer.albedo);
                d.gbuffer.normalMaterial = builder.read(gbuffer.normalMaterial);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                d.out.irradiance = builder.create("irradiance", {w, h, graph::TextureFormat::Rgba16F});
                d.out.specular = builder.create("specular", {w, h, graph::TextureFormat::Rgba16F});
            },
            [&frame](const graph::PassResources& resources, const LightingData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out.irradiance);
                attachments.colour[1] = resources.texture(d.out.specular);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->lighting.get());
                glBindTextureUnit(0, resources.texture(d.gbuffer.depthStencil));
                glBindTextureUnit(1, resources.texture(d.gbuffer.albedo));
                glBindTextureUnit(2, resources.texture(d.gbuffer.normalMaterial));
                glBindTextureUnit(3, frame.beckmannTable);
                for (size_t slot = 0; slot < DERMIS_MAX_SHADOWED_LIGHTS; ++slot) {
                    // Unused slots get a valid texture too: sampler arrays must be complete.
                    const GLuint map = slot < d.shadowMaps.size() ? resources.texture(d.shadowMaps[slot])
                                                                  : frame.beckmannTable;
                    glBindTextureUnit(static_cast<GLuint>(4 + slot), map);
                }
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
