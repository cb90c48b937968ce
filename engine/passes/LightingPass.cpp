#include "passes/LightingPass.h"

#include "passes/FullscreenPass.h"

namespace dermis {
namespace {
struct LightingData {
    GBuffer gbuffer;
    std::vector<graph::TextureHandle> shadowMaps;
    graph::TextureHandle ambientOcclusion;
    graph::TextureHandle leanCross;
    graph::TextureHandle scatter;  // read where a technique scatters in this pass (render/LightingScatter.h): slot, curvature
    Lighting out;
};
}  // namespace

void bindShadowMaps(const FrameContext& frame, const graph::PassResources& resources,
                    const std::vector<graph::TextureHandle>& shadowMaps) {
    for (size_t slot = 0; slot < DERMIS_MAX_SHADOWED_LIGHTS; ++slot) {
        const GLuint map = slot < shadowMaps.size() ? resources.texture(shadowMaps[slot]) : frame.gl->whiteTexture;
        glBindTextureUnit(static_cast<GLuint>(4 + slot), map);
    }
}

Lighting addLightingPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                         const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle ambientOcclusion,
                         bool shadowVisibility) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    return graph
        .addPass<LightingData>(
            "lighting",
            [&](graph::PassBuilder& builder, LightingData& d) {
                d.gbuffer.depthStencil = builder.read(gbuffer.depthStencil);
                d.gbuffer.albedo = builder.read(gbuffer.albedo);
                d.gbuffer.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.ambientOcclusion = builder.read(ambientOcclusion);
                if (gbuffer.hasLean()) d.leanCross = builder.read(gbuffer.leanCross);
                if (gbuffer.environment.isValid()) d.gbuffer.environment = builder.read(gbuffer.environment);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                if (frame.plan.sss.anyScattersInLighting()) {
                    d.scatter = builder.read(gbuffer.scatter);
                }
                d.out.irradiance = builder.create("irradiance", {w, h, graph::TextureFormat::Rgba16F});
                d.out.specular = builder.create("specular", {w, h, graph::TextureFormat::Rgba16F});
                if (shadowVisibility) d.out.visibility = builder.create("shadow visibility", {w, h, graph::TextureFormat::Rgba8});
            },
            [frame](const graph::PassResources& resources, const LightingData& d) {
                const bool lean = d.leanCross.isValid();
                const Programs& programs = *frame.gl->programs;
                beginFullscreenPass(frame, resources, {{d.out.irradiance, d.out.specular, d.out.visibility}},
                                    (lean ? programs.lightingLean : programs.lighting)
                                        .get(frame.plan.environment.enabled(), frame.plan.lights.shadowCode,
                                             frame.plan.sss.anyScattersInLighting()),
                                    {d.gbuffer.depthStencil, d.gbuffer.albedo, d.gbuffer.normalMaterial,
                                     d.ambientOcclusion});
                bindShadowMaps(frame, resources, d.shadowMaps);
                if (lean) glBindTextureUnit(8, resources.texture(d.leanCross));
                if (d.gbuffer.environment.isValid()) glBindTextureUnit(9, resources.texture(d.gbuffer.environment));
                if (d.scatter.isValid()) {
                    glBindTextureUnit(10, resources.texture(d.scatter));
                    glBindTextureUnit(DERMIS_UNIT_FIRST_PASS_EXTRA, frame.gl->lightingTables);
                }
                frame.gl->drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
