#include "passes/TextureSpacePasses.h"

#include "core/Log.h"
#include "passes/TsPassSteps.h"
#include "render/ScreenFootprint.h"

#include <algorithm>

namespace dermis {
namespace {

struct InitData {
    graph::TextureHandle irradiance, accumulated;
};
struct GatherData {
    std::vector<graph::TextureHandle> blurred;
    graph::TextureHandle tsm, depthStencil, albedo, accumulatedIn, accumulatedOut;
};

graph::TextureHandle addInitPass(graph::RenderGraph& graph, FrameContext& frame, graph::TextureHandle irradiance) {
    const bool anyVisible = frame.textureSpace->plan.anyVisible();
    return graph
        .addPass<InitData>(
            "ts init",
            [&](graph::PassBuilder& builder, InitData& d) {
                d.irradiance = builder.read(irradiance);
                // The same format as the irradiance, for the copy.
                d.accumulated = builder.create("ts accumulated", builder.desc(irradiance));
                builder.passThrough(d.accumulated, irradiance);
                builder.skipIf(!frame.scene->settings.sss.enabled, "SSS disabled");
                builder.skipIf(!anyVisible, "no texture-space character on screen");
            },
            [&frame](const graph::PassResources& resources, const InitData& d) {
                glCopyImageSubData(resources.texture(d.irradiance), GL_TEXTURE_2D, 0, 0, 0, 0,
                                   resources.texture(d.accumulated), GL_TEXTURE_2D, 0, 0, 0, 0, frame.width, frame.height,
                                   1);
            })
        .accumulated;
}

graph::TextureHandle addGatherPass(graph::RenderGraph& graph, FrameContext& frame, const TsCharacterPlan& plan,
                                   const GBuffer& gbuffer, const std::vector<graph::TextureHandle>& blurred,
                                   graph::TextureHandle tsm, graph::TextureHandle accumulated) {
    const std::string name = tsPassName(plan, "gather");
    return graph
        .addPass<GatherData>(
            name,
            [&](graph::PassBuilder& builder, GatherData& d) {
                for (graph::TextureHandle texture : blurred) d.blurred.push_back(builder.read(texture));
                d.tsm = builder.read(tsm);
                d.depthStencil = builder.read(gbuffer.depthStencil);
                d.albedo = builder.read(gbuffer.albedo);
                d.accumulatedIn = builder.read(accumulated);
                d.accumulatedOut = builder.write(accumulated);
                builder.skipIf(!plan.visible, "character off screen");
            },
            [&frame, plan](const graph::PassResources& resources, const GatherData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.accumulatedOut);
                attachments.depth = resources.texture(d.depthStencil);
                attachments.depthHasStencil = true;
                frame.framebuffers->bind(attachments);
                frame.setViewport(frame.width, frame.height);
                glUseProgram(frame.programs->tsGather.get());
                for (size_t i = 0; i < DERMIS_MAX_PROFILE_GAUSSIANS; ++i) {
                    const GLuint texture = i < d.blurred.size() ? resources.texture(d.blurred[i]) : frame.blackTexture;
                    glBindTextureUnit(static_cast<GLuint>(i), texture);
                }
                glBindTextureUnit(8, resources.texture(d.tsm));
                glBindTextureUnit(9, resources.texture(d.albedo));
                uploadTsBlocks(frame, plan, textureSpaceBlock(frame, plan));
                // Only the surface the G-buffer kept: its own depth, pulled a
                // little towards the camera so that the two programs' rounding
                // cannot make it fail; the object id check in the shader rules
                // out other characters within that margin.
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LEQUAL);
                glDepthMask(GL_FALSE);
                glEnable(GL_POLYGON_OFFSET_FILL);
                glPolygonOffset(-1.0f, -2.0f);
                glDisable(GL_CULL_FACE);
                drawTsMesh(frame, plan);
                glDisable(GL_POLYGON_OFFSET_FILL);
                glDepthMask(GL_TRUE);
                glDepthFunc(GL_LESS);
                glDisable(GL_DEPTH_TEST);
            })
        .accumulatedOut;
}

}  // namespace

Status planTextureSpaceFrame(FrameContext& frame) {
    if (!frame.textureSpace) frame.textureSpace = std::make_shared<TextureSpaceState>();
    TextureSpaceState& state = *frame.textureSpace;
    const Scene& scene = *frame.scene;
    const auto& characters = frame.gpuScene->characters();
    std::vector<TsCharacterInput> inputs;
    for (size_t c = 0; c < characters.size() && c < scene.characters.size(); ++c) {
        TsCharacterInput input;
        input.worldBounds = characters[c].worldBounds;
        if (scene.characters[c].material.profile != kOpaqueProfile) {
            const TsMesh& mesh = state.meshes.get(c, characters[c]);
            const float mmPerUnit = glm::length(glm::vec3(characters[c].worldFromObject[0])) * 1000.0f;
            input.mmPerUv = mesh.medianStretch * mmPerUnit;
            input.denseMmPerUv = mesh.denseStretch * mmPerUnit;
        }
        inputs.push_back(input);
    }
    auto plan = planTextureSpace(scene, inputs, makeViewParams(scene.camera, frame.width, frame.height), frame.lights);
    if (!plan.ok()) {
        state.plan = TsPlan{};
        return plan.error();
    }
    state.plan = std::move(*plan);
    return success();
}

graph::TextureHandle addTextureSpacePasses(graph::RenderGraph& graph, FrameContext& frame, const GBuffer& gbuffer,
                                           const std::vector<graph::TextureHandle>& shadowMaps,
                                           graph::TextureHandle ambientOcclusion, graph::TextureHandle irradiance) {
    if (const Status planned = planTextureSpaceFrame(frame); !planned.ok()) {
        log::error("texture-space SSS: " + planned.error().message());
        return irradiance;
    }
    auto kernel = makeGaussianKernel(frame.scene->settings.ts.taps);
    if (!kernel.ok()) return irradiance;  // the scene loader validates taps
    const graph::TextureHandle black =
        graph.importTexture("ts black", {1, 1, graph::TextureFormat::Rgba8}, frame.blackTexture);

    graph::TextureHandle accumulated = addInitPass(graph, frame, irradiance);
    for (const TsCharacterPlan& plan : frame.textureSpace->plan.characters) {
        const graph::TextureHandle tsm = addTsmPass(graph, frame, plan, black);
        const graph::TextureHandle stretch = addTsStretchPass(graph, frame, plan);
        const graph::TextureHandle raw = addIrradiancePass(graph, frame, plan, gbuffer, shadowMaps, ambientOcclusion, tsm);
        const graph::TextureHandle dilated = addDilatePass(graph, frame, plan, raw);
        const std::vector<graph::TextureHandle> blurred = addBlurPasses(graph, frame, plan, *kernel, stretch, dilated);
        accumulated = addGatherPass(graph, frame, plan, gbuffer, blurred, tsm, accumulated);
    }
    return accumulated;
}

graph::TextureHandle addTsAovPasses(graph::RenderGraph& graph, FrameContext& frame, Aov aov, const GBuffer& gbuffer,
                                    const std::vector<graph::TextureHandle>& shadowMaps,
                                    graph::TextureHandle ambientOcclusion, graph::TextureHandle none) {
    if (const Status planned = planTextureSpaceFrame(frame); !planned.ok()) {
        log::error("texture-space SSS: " + planned.error().message());
        return none;
    }
    const auto& characters = frame.textureSpace->plan.characters;
    const auto first =
        std::find_if(characters.begin(), characters.end(), [](const TsCharacterPlan& c) { return c.visible; });
    if (first == characters.end()) return none;
    if (aov == Aov::Stretch) return addTsStretchPass(graph, frame, *first);
    const graph::TextureHandle tsm = addTsmPass(graph, frame, *first, none);
    return addIrradiancePass(graph, frame, *first, gbuffer, shadowMaps, ambientOcclusion, tsm);
}

}  // namespace dermis
