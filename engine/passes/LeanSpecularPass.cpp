#include "passes/LeanSpecularPass.h"

namespace dermis {
namespace {
struct LeanSpecularData {
    graph::TextureHandle depth, albedo, normalMaterial, moments, accumulated, visibility, specular, out;
};
}  // namespace

graph::TextureHandle addLeanSpecularPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                         const LeanShading& lean, graph::TextureHandle lightingSpecular) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
    return graph
        .addPass<LeanSpecularData>(
            "lean specular",
            [&](graph::PassBuilder& builder, LeanSpecularData& d) {
                d.depth = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.moments = builder.read(lean.moments);
                d.accumulated = builder.read(lean.accumulated);
                d.visibility = builder.read(lean.visibility);
                d.specular = builder.read(lightingSpecular);
                d.out = builder.create("lean specular", {w, h, graph::TextureFormat::Rgba16F});
            },
            [&frame](const graph::PassResources& resources, const LeanSpecularData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->leanSpecular.get());
                glBindTextureUnit(0, resources.texture(d.depth));
                glBindTextureUnit(1, resources.texture(d.albedo));
                glBindTextureUnit(2, resources.texture(d.normalMaterial));
                glBindTextureUnit(3, resources.texture(d.moments));
                glBindTextureUnit(4, resources.texture(d.accumulated));
                glBindTextureUnit(5, resources.texture(d.visibility));
                glBindTextureUnit(6, resources.texture(d.specular));
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
