#include "passes/TransmittancePass.h"

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

bool anyBackLight(const FrameContext& frame) {
    for (int index : frame.lights.shadowedLights) {
        if (frame.lights.block.lights[index].shadowDepth.w > 0.5f) return true;
    }
    return false;
}

graph::TextureHandle addTransmittancePass(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                          const std::vector<graph::TextureHandle>& shadowMaps,
                                          graph::TextureHandle addInto, graph::TextureHandle black) {
    const TransmittanceSettings& settings = frame.scene->settings.transmittance;
    const bool ownTarget = !addInto.isValid();
    return graph
        .addPass<TransmittanceData>(
            "transmittance",
            [&](graph::PassBuilder& builder, TransmittanceData& d) {
                d.gbuffer.depthStencil = builder.read(gbuffer.depthStencil);
                d.gbuffer.albedo = builder.read(gbuffer.albedo);
                d.gbuffer.normalMaterial = builder.read(gbuffer.normalMaterial);
                d.gbuffer.depthKey = builder.read(gbuffer.depthKey);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                if (ownTarget) {
                    d.out = builder.create("transmitted", {static_cast<uint32_t>(frame.width),
                                                           static_cast<uint32_t>(frame.height),
                                                           graph::TextureFormat::Rgba16F});
                    builder.passThrough(d.out, black);
                } else {
                    d.in = builder.read(addInto);
                    d.out = builder.write(addInto);
                }
                builder.skipIf(!settings.enabled, "transmittance disabled");
                builder.skipIf(!frame.sss.anyVisible(), "no SSS pixel on screen");
                builder.skipIf(!anyBackLight(frame), "no shadowed light behind an SSS character");
            },
            [&frame, ownTarget](const graph::PassResources& resources, const TransmittanceData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.out);
                attachments.depth = resources.texture(d.gbuffer.depthStencil);
                attachments.depthHasStencil = true;
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                if (ownTarget) {
                    const float zero[4] = {0, 0, 0, 0};
                    glClearBufferfv(GL_COLOR, 0, zero);
                }
                glUseProgram(frame.programs->transmittance.get());
                glBindTextureUnit(1, resources.texture(d.gbuffer.albedo));
                glBindTextureUnit(2, resources.texture(d.gbuffer.normalMaterial));
                glBindTextureUnit(3, resources.texture(d.gbuffer.depthKey));
                bindShadowMaps(frame, resources, d.shadowMaps);
                const ScopedSssState state(frame, sssScissor(frame.sss), kAnySssPixel);
                glEnablei(GL_BLEND, 0);
                glBlendFunci(0, GL_ONE, GL_ONE);
                frame.drawFullscreenTriangle();
                glDisablei(GL_BLEND, 0);
            })
        .out;
}

}  // namespace dermis
