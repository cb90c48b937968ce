#include "passes/AovPass.h"

#include "passes/FullscreenPass.h"

namespace dermis {
namespace {
struct AovData {
    graph::TextureHandle depth, albedo, normalMaterial, diffuse, specular, component, unscattered, scatter, out;
};
}  // namespace

graph::TextureHandle addAovPass(graph::RenderGraph& graph, const FrameContext& frame, const AovInputs& inputs,
                                graph::TextureHandle output) {
    return graph
        .addPass<AovData>(
            "aov",
            [&](graph::PassBuilder& builder, AovData& d) {
                d.depth = builder.read(inputs.gbuffer.depthStencil);
                d.albedo = builder.read(inputs.gbuffer.albedo);
                d.normalMaterial = builder.read(inputs.gbuffer.normalMaterial);
                if (frame.plan.aov == Aov::Diffuse) {
                    d.diffuse = builder.read(inputs.diffuse);
                    d.unscattered = builder.read(inputs.unscattered);
                }
                if (frame.plan.aov == Aov::Diffuse || frame.plan.aov == Aov::Scatter)
                    d.scatter = builder.read(inputs.gbuffer.scatter);
                if (frame.plan.aov == Aov::Specular) d.specular = builder.read(inputs.specular);
                if (inputs.component.isValid()) d.component = builder.read(inputs.component);
                d.out = builder.write(output);
            },
            [frame](const graph::PassResources& resources, const AovData& d) {
                // What the AOV does not read is bound as the albedo (every sampler needs a texture).
                auto orAlbedo = [&](graph::TextureHandle h) { return h.isValid() ? h : d.albedo; };
                runFullscreenPass(frame, resources, {{d.out}}, frame.gl->programs->aov.get(),
                                  {d.depth, d.albedo, orAlbedo(d.diffuse), orAlbedo(d.specular), d.normalMaterial,
                                   orAlbedo(d.component), {}, orAlbedo(d.unscattered), orAlbedo(d.scatter)});
            })
        .out;
}

}  // namespace dermis
