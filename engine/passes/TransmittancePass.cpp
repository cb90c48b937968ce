#include "passes/TransmittancePass.h"

#include "passes/FullscreenPass.h"
#include "passes/LightingPass.h"
#include "passes/SssPasses.h"

namespace dermis {
namespace {
struct TransmittanceData {
    GBuffer gbuffer;
    std::vector<graph::TextureHandle> shadowMaps;
    graph::TextureHandle in;
    graph::TextureHandle out;
};
}  // namespace

graph::TextureHandle addTransmittancePass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                          const std::vector<graph::TextureHandle>& shadowMaps,
                                          graph::TextureHandle addInto, graph::TextureHandle black) {
    const TransmittanceSettings& settings = frame.plan.scene->settings.transmittance;
    const bool ownTarget = !addInto.isValid();
    return graph
        .addPass<TransmittanceData>(
            "transmittance",
            [&](graph::PassBuilder& builder, TransmittanceData& d) {
                d.gbuffer = readSurfaceTargets(builder, gbuffer);
                d.gbuffer.scatter = builder.read(gbuffer.scatter);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                if (ownTarget) {
                    d.out = builder.create("transmitted", {static_cast<uint32_t>(frame.plan.width),
                                                           static_cast<uint32_t>(frame.plan.height),
                                                           graph::TextureFormat::Rgba16F});
                    builder.passThrough(d.out, black);
                } else {
                    d.in = builder.read(addInto);
                    d.out = builder.write(addInto);
                }
                builder.skipIf(!settings.enabled, "transmittance disabled");
                builder.skipIf(!frame.plan.scene->settings.sss.enabled, "SSS disabled");
                builder.skipIf(!frame.plan.sss.anyVisible(), "no SSS pixel on screen");
                builder.skipIf(!frame.plan.anyBackLight, "no shadowed light behind an SSS character");
            },
            [frame, ownTarget](const graph::PassResources& resources, const TransmittanceData& d) {
                // Unit 0 is not sampled: depth comes from the depth key. Units 4-7 are the shadow maps.
                beginFullscreenPass(frame, resources, {{d.out}, d.gbuffer.depthStencil},
                                    frame.gl->programs->transmittance.get(),
                                    {{}, d.gbuffer.albedo, d.gbuffer.normalMaterial, d.gbuffer.depthKey, {}, {}, {}, {},
                                     d.gbuffer.scatter});
                if (ownTarget) {
                    const float zero[4] = {0, 0, 0, 0};
                    glClearBufferfv(GL_COLOR, 0, zero);
                }
                bindShadowMaps(frame, resources, d.shadowMaps);
                const ScopedSssState state(frame, sssScissor(frame.plan.sss), kAnySssPixel);
                glEnablei(GL_BLEND, 0);
                glBlendFunci(0, GL_ONE, GL_ONE);
                frame.gl->drawFullscreenTriangle();
                glDisablei(GL_BLEND, 0);
            })
        .out;
}

}  // namespace dermis
