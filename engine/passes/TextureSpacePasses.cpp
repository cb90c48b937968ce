#include "passes/TextureSpacePasses.h"

#include "passes/TsPassSteps.h"

#include <algorithm>

namespace dermis {
namespace {

struct InitData {
    graph::TextureHandle irradiance, accumulated;
};
struct GatherData {
    std::vector<graph::TextureHandle> blurred;
    graph::TextureHandle tsm, depthStencil, albedo, depthKey, irradiance, hiddenSide, accumulatedIn, accumulatedOut;
};

// The accumulation starts as `base`: the lighting's irradiance, or the
// screen-space chain's result when a character falls back to it.
graph::TextureHandle addInitPass(graph::RenderGraph& graph, const FrameContext& frame, graph::TextureHandle base) {
    const bool anyRuns = frame.plan.ts.anyRuns();
    return graph
        .addPass<InitData>(
            "ts init",
            [&](graph::PassBuilder& builder, InitData& d) {
                d.irradiance = builder.read(base);
                // The same format as the base, for the copy.
                d.accumulated = builder.create("ts accumulated", builder.desc(base));
                builder.passThrough(d.accumulated, base);
                builder.skipIf(!frame.plan.scene->settings.sss.enabled, "SSS disabled");
                builder.skipIf(!anyRuns, "no texture-space character on screen");
            },
            [frame](const graph::PassResources& resources, const InitData& d) {
                glCopyImageSubData(resources.texture(d.irradiance), GL_TEXTURE_2D, 0, 0, 0, 0,
                                   resources.texture(d.accumulated), GL_TEXTURE_2D, 0, 0, 0, 0, frame.plan.width, frame.plan.height,
                                   1);
            })
        .accumulated;
}

graph::TextureHandle addGatherPass(graph::RenderGraph& graph, const FrameContext& frame, const TsCharacterPlan& plan,
                                   const GBuffer& gbuffer, const std::vector<graph::TextureHandle>& blurred,
                                   graph::TextureHandle tsm, graph::TextureHandle irradiance,
                                   graph::TextureHandle hiddenSide, graph::TextureHandle accumulated) {
    const std::string name = tsPassName(plan, "gather");
    return graph
        .addPass<GatherData>(
            name,
            [&](graph::PassBuilder& builder, GatherData& d) {
                for (graph::TextureHandle texture : blurred) d.blurred.push_back(builder.read(texture));
                d.tsm = builder.read(tsm);
                d.depthStencil = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.depthKey = builder.read(gbuffer.depthKey);
                d.irradiance = builder.read(irradiance);
                d.hiddenSide = builder.read(hiddenSide);
                d.accumulatedIn = builder.read(accumulated);
                d.accumulatedOut = builder.write(accumulated);
                builder.skipIf(!plan.runs(), plan.skipReason());
            },
            [frame, plan](const graph::PassResources& resources, const GatherData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.accumulatedOut);
                attachments.depth = resources.texture(d.depthStencil);
                attachments.depthHasStencil = true;
                frame.gl->framebuffers->bind(attachments);
                frame.gl->setViewport(frame.plan.width, frame.plan.height);
                glUseProgram(frame.gl->programs->tsGather.get());
                for (size_t i = 0; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
                    const GLuint texture = i < d.blurred.size() ? resources.texture(d.blurred[i]) : frame.gl->blackTexture;
                    glBindTextureUnit(static_cast<GLuint>(i), texture);
                }
                glBindTextureUnit(8, resources.texture(d.tsm));
                glBindTextureUnit(9, resources.texture(d.albedo));
                glBindTextureUnit(10, resources.texture(d.depthKey));
                glBindTextureUnit(DERMIS_UNIT_TS_PIXEL_IRRADIANCE, resources.texture(d.irradiance));
                glBindTextureUnit(DERMIS_UNIT_HIDDEN_SIDE, resources.texture(d.hiddenSide));
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                // Only the surface the G-buffer kept: its own depth, pulled a
                // little towards the camera so that the two programs' rounding
                // cannot make it fail. The margin grows with the depth slope, so
                // at grazing angles surfaces millimetres behind pass too; the
                // shader rules them out by the view depth the G-buffer stored,
                // and other characters by the object id.
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
                glDepthMask(GL_FALSE);
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(-1.0f, -2.0f);
                glDisable(GL_CULL_FACE);
                drawTsMesh(frame, plan, TsDraw::Surface);
                glDisable(GL_POLYGON_OFFSET_FILL);
                glDepthMask(GL_TRUE);
                glDepthFunc(GL_LESS);
                glDisable(GL_DEPTH_TEST);
            })
        .accumulatedOut;
}

}  // namespace

graph::TextureHandle addTextureSpacePasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                           const std::vector<graph::TextureHandle>& shadowMaps,
                                           graph::TextureHandle ambientOcclusion, graph::TextureHandle irradiance,
                                           graph::TextureHandle base, graph::TextureHandle hiddenSide,
                                           graph::TextureHandle black) {
    graph::TextureHandle accumulated = addInitPass(graph, frame, base);
    for (const TsCharacterPlan& plan : frame.plan.ts.characters) {
        const graph::TextureHandle tsm = addTsmPass(graph, frame, plan, black);
        const graph::TextureHandle stretch = addTsStretchPass(graph, frame, plan);
        const graph::TextureHandle raw = addIrradiancePass(graph, frame, plan, gbuffer, shadowMaps, ambientOcclusion, tsm);
        const graph::TextureHandle dilated = addDilatePass(graph, frame, plan, raw);
        const std::vector<graph::TextureHandle> blurred = addBlurPasses(graph, frame, plan, stretch, dilated);
        accumulated = addGatherPass(graph, frame, plan, gbuffer, blurred, tsm, irradiance, hiddenSide, accumulated);
    }
    return accumulated;
}

graph::TextureHandle addTsAovPasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                    const std::vector<graph::TextureHandle>& shadowMaps,
                                    graph::TextureHandle ambientOcclusion, graph::TextureHandle none) {
    const auto& characters = frame.plan.ts.characters;
    const auto first =
        std::find_if(characters.begin(), characters.end(), [](const TsCharacterPlan& c) { return c.runs(); });
    if (first == characters.end()) return none;
    if (frame.plan.aov == Aov::Stretch) return addTsStretchPass(graph, frame, *first);
    const graph::TextureHandle tsm = addTsmPass(graph, frame, *first, none);
    return addIrradiancePass(graph, frame, *first, gbuffer, shadowMaps, ambientOcclusion, tsm);
}

}  // namespace dermis
