#include "passes/AovPass.h"

namespace dermis {
namespace {
struct AovData {
    graph::TextureHandle depth, albedo, normalMaterial, diffuse, specular, component, out;
};
}  // namespace

graph::TextureHandle addAovPass(graph::RenderGraph& graph, FrameContext& frame, const AovInputs& inputs,
                                graph::TextureHandle output) {
    return graph
        .addPass<AovData>(
            "aov",
            [&](graph::PassBuilder& builder, AovData& d) {
                d.depth = builder.read(inputs.gbuffer.depthStencil);
                d.albedo = builder.read(inputs.gbuffer.albedo);
                d.normalMaterial = builder.read(inputs.gbuffer.normalMaterial);
                if (frame.aov == Aov::Diffuse) d.diffuse = builder.read(inputs.diffuse);
                if (frame.aov == Aov::Specular) d.specular = builder.read(inputs.specular);
                if (inputs.component.isValid()) d.component = builder.read(inputs.component);
                d.out = builder.write(output);
            },
            [&frame](const graph::PassResources& resources, const AovData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->aov.get());
                const GLuint albedo = resources.texture(d.albedo);
                auto orAlbedo = [&](graph::TextureHandle h) { return h.isValid() ? resources.texture(h) : albedo; };
                glBindTextureUnit(0, resources.texture(d.depth));
                glBindTextureUnit(1, albedo);
                glBindTextureUnit(2, orAlbedo(d.diffuse));
                glBindTextureUnit(3, orAlbedo(d.specular));
                glBindTextureUnit(4, resources.texture(d.normalMaterial));
                glBindTextureUnit(5, orAlbedo(d.component));
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
