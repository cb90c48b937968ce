#include "passes/CompositePass.h"

namespace dermis {
namespace {
struct CompositeData {
    graph::TextureHandle depth, albedo, normalMaterial, diffuse, specular, out;
    LeanShading lean;
};
struct TonemapData {
    graph::TextureHandle hdr, out;
};
}  // namespace

graph::TextureHandle addCompositePass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                      graph::TextureHandle diffuse, graph::TextureHandle specular,
                                      const LeanShading& lean) {
    const auto w = static_cast<uint32_t>(frame.width);
    const auto h = static_cast<uint32_t>(frame.height);
    return graph
        .addPass<CompositeData>(
            "composite",
            [&](graph::PassBuilder& builder, CompositeData& d) {
                d.depth = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.diffuse = builder.read(diffuse);
                d.specular = builder.read(specular);
                if (lean.isValid()) {
                    d.lean.moments = builder.read(lean.moments);
                    d.lean.visibility = builder.read(lean.visibility);  // lean.accumulated is `diffuse`
                }
                d.out = builder.create("hdr colour", {w, h, graph::TextureFormat::Rgba16F});
            },
            [&frame](const graph::PassResources& resources, const CompositeData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(d.lean.isValid() ? frame.programs->compositeLean.get() : frame.programs->composite.get());
                if (d.lean.isValid()) {
                    glBindTextureUnit(5, resources.texture(d.lean.moments));
                    glBindTextureUnit(6, resources.texture(d.lean.visibility));
                }
                glBindTextureUnit(0, resources.texture(d.depth));
                glBindTextureUnit(1, resources.texture(d.albedo));
                glBindTextureUnit(2, resources.texture(d.diffuse));
                glBindTextureUnit(3, resources.texture(d.specular));
                glBindTextureUnit(4, resources.texture(d.normalMaterial));
                frame.drawFullscreenTriangle();
            })
        .out;
}

graph::TextureHandle addTonemapPass(graph::RenderGraph& graph, FrameContext& frame, graph::TextureHandle hdr,
                                    graph::TextureHandle output) {
    return graph
        .addPass<TonemapData>(
            "tonemap",
            [&](graph::PassBuilder& builder, TonemapData& d) {
                d.hdr = builder.read(hdr);
                d.out = builder.write(output);
            },
            [&frame](const graph::PassResources& resources, const TonemapData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->tonemap.get());
                glBindTextureUnit(0, resources.texture(d.hdr));
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
