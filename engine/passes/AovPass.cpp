#include "passes/AovPass.h"

namespace dermis {
namespace {
struct AovData {
    graph::TextureHandle depth, albedo, normalMaterial, irradiance, specular, out;
};
bool needsLighting(Aov aov) { return aov == Aov::Diffuse || aov == Aov::Specular || aov == Aov::Irradiance; }
}  // namespace

graph::TextureHandle addAovPass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                const Lighting& lighting, graph::TextureHandle output) {
    return graph
        .addPass<AovData>(
            "aov",
            [&](graph::PassBuilder& builder, AovData& d) {
                d.depth = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.normalMaterial = builder.read(gbuffer.normalMaterial);
                if (needsLighting(frame.aov)) {
                    d.irradiance = builder.read(lighting.irradiance);
                    d.specular = builder.read(lighting.specular);
                }
                d.out = builder.write(output);
            },
            [&frame](const graph::PassResources& resources, const AovData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->aov.get());
                glBindTextureUnit(0, resources.texture(d.depth));
                glBindTextureUnit(1, resources.texture(d.albedo));
                glBindTextureUnit(2, resources.texture(d.normalMaterial));
                const bool lit = d.irradiance.isValid();
                glBindTextureUnit(3, lit ? resources.texture(d.irradiance) : resources.texture(d.albedo));
                glBindTextureUnit(4, lit ? resources.texture(d.specular) : resources.texture(d.albedo));
                frame.drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
