#include "passes/LeanSpecularPass.h"

#include "passes/FullscreenPass.h"

namespace dermis {
namespace {
struct LeanSpecularData {
    graph::TextureHandle depth, albedo, normalMaterial, moments, accumulated, visibility, specular, out;
};
}  // namespace

graph::TextureHandle addLeanSpecularPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                         const LeanShading& lean, graph::TextureHandle lightingSpecular) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
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
            [frame](const graph::PassResources& resources, const LeanSpecularData& d) {
                runFullscreenPass(frame, resources, {{d.out}}, frame.gl->programs->leanSpecular.get(frame.plan.environment.enabled()),
                                  {d.depth, d.albedo, d.normalMaterial, d.moments, d.accumulated, d.visibility,
                                   d.specular});
            })
        .out;
}

}  // namespace dermis
