#include "passes/CompositePass.h"

#include "passes/FullscreenPass.h"

namespace dermis {
namespace {
struct CompositeData {
    graph::TextureHandle depth, albedo, normalMaterial, diffuse, unscattered, scatter, specular, out;
    LeanShading lean;
};
struct TonemapData {
    graph::TextureHandle hdr, out;
};
}  // namespace

graph::TextureHandle addCompositePass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                      graph::TextureHandle diffuse, graph::TextureHandle unscattered,
                                      graph::TextureHandle specular,
                                      const LeanShading& lean) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    return graph
        .addPass<CompositeData>(
            "composite",
            [&](graph::PassBuilder& builder, CompositeData& d) {
                d.depth = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.diffuse = builder.read(diffuse);
                d.unscattered = builder.read(unscattered);
                d.scatter = builder.read(gbuffer.scatter);
                d.specular = builder.read(specular);
                if (lean.isValid()) {
                    d.lean.moments = builder.read(lean.moments);
                    d.lean.visibility = builder.read(lean.visibility);  // lean.accumulated is `diffuse`
                }
                d.out = builder.create("hdr colour", {w, h, graph::TextureFormat::Rgba16F});
            },
            [frame, regions = characterRegions(frame.plan)](const graph::PassResources& resources,
                                                             const CompositeData& d) {
                const Programs& programs = *frame.gl->programs;
                // Units 5 and 6 only in the LEAN variants (invalid handles otherwise).
                beginFullscreenPass(frame, resources, {{d.out}},
                                  d.lean.isValid() ? programs.compositeLean.get(frame.plan.environment.enabled())
                                                    : programs.composite.get(),
                                  {d.depth, d.albedo, d.diffuse, d.specular, d.normalMaterial, d.lean.moments,
                                   d.lean.visibility, d.unscattered, d.scatter});
                // The background is the scene's colour (composite.frag).
                drawCharacterPixels(frame, regions, 1, glm::vec4(frame.plan.scene->background.colour, 1.0f));
            })
        .out;
}

graph::TextureHandle addTonemapPass(graph::RenderGraph& graph, const FrameContext& frame, graph::TextureHandle hdr,
                                    graph::TextureHandle output) {
    return graph
        .addPass<TonemapData>(
            "tonemap",
            [&](graph::PassBuilder& builder, TonemapData& d) {
                d.hdr = builder.read(hdr);
                d.out = builder.write(output);
            },
            [frame](const graph::PassResources& resources, const TonemapData& d) {
                runFullscreenPass(frame, resources, {{d.out}}, frame.gl->programs->tonemap.get(), {d.hdr});
            })
        .out;
}

}  // namespace dermis
