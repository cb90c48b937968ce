#include "passes/SkyboxPass.h"

#include "passes/FullscreenPass.h"

namespace dermis {
namespace {
struct SkyboxData {
    graph::TextureHandle depth, hdr;
};

std::string skyboxSkipReason(const FramePlan& plan) {
    if (!plan.environment.enabled()) return "the scene has no environment";
    if (!plan.scene->environment.background) return "environment.background is false: the background colour shows";
    return "the output is not a colour image";
}
}  // namespace

graph::TextureHandle addSkyboxPass(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                   graph::TextureHandle hdr) {
    return graph
        .addPass<SkyboxData>(
            "skybox",
            [&](graph::PassBuilder& builder, SkyboxData& d) {
                d.depth = builder.read(gbuffer.depthStencil);
                // It draws over the composite's colour, which must exist first.
                d.hdr = builder.write(builder.read(hdr));
                const bool skip = !frame.plan.environment.skybox;
                builder.skipIf(skip, skip ? skyboxSkipReason(frame.plan) : std::string());
            },
            [frame](const graph::PassResources& resources, const SkyboxData& d) {
                beginFullscreenPass(frame, resources, {{d.hdr}, d.depth}, frame.gl->programs->skybox.get(), {});
                glBindTextureUnit(0, frame.gl->environment->background());
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
                glDepthMask(GL_FALSE);
                frame.gl->drawFullscreenTriangle();
                glDepthMask(GL_TRUE);
                glDisable(GL_DEPTH_TEST);
            })
        .hdr;
}

}  // namespace dermis
