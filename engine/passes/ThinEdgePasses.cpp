#include "passes/ThinEdgePasses.h"

#include "passes/FullscreenPass.h"
#include "passes/LightingPass.h"
#include "passes/SssPasses.h"

namespace dermis {
namespace {

struct BackFaces {
    graph::TextureHandle depth;   // D32F
    graph::TextureHandle normal;  // RG16F: octahedral view normal
};

struct HiddenSideData {
    GBuffer gbuffer;
    BackFaces back;
    std::vector<graph::TextureHandle> shadowMaps;
    graph::TextureHandle out;
};

void skipUnlessNeeded(graph::PassBuilder& builder, const FrameContext& frame) {
    const RenderSettings& settings = frame.plan.scene->settings;
    builder.skipIf(!settings.transmittance.thinEdges, "thin edges disabled (settings.transmittance.thin_edges = false)");
    builder.skipIf(!settings.sss.enabled, "SSS disabled");
    builder.skipIf(!frame.plan.sss.anyVisible(), "no SSS pixel on screen");
}

// Whether any of the character's pixels reads the fill: a slot that some
// pass blurs on screen (blursOnScreen: not the pre-integrated technique, which
// scatters in the lighting pass, nor a chain whose every Gaussian is under
// min_width_px), or any SSS slot in texture space, whose gather reads it. Far
// heads of a crowd are left out of the back-depth draw: in crowd8_mixed.json
// at 640x360 it took 40 ms with every head in it.
bool readsThinEdges(const FramePlan& plan, size_t character) {
    if (character >= plan.sss.slotsOfCharacter.size()) return false;
    for (const int slot : plan.sss.slotsOfCharacter[character]) {
        if (slot <= 0) continue;
        if (plan.textureSpace) return true;
        for (const SssSlotPlan& slotPlan : plan.sss.slots) {
            if (slotPlan.slot == slot && blursOnScreen(slotPlan)) return true;
        }
    }
    return false;
}

// The nearest back face behind each pixel, its depth and normal: the visible
// characters drawn with their front faces culled. A character whose mesh is
// open shows a back face through the opening; the thin-edge pass then
// measures a path to it, which only matters where the opening meets an outline.
BackFaces addBackDepthPass(graph::RenderGraph& graph, const FrameContext& frame) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    return graph
        .addPass<BackFaces>(
            "back depth",
            [&](graph::PassBuilder& builder, BackFaces& d) {
                d.depth = builder.create("back depth", {w, h, graph::TextureFormat::Depth32F});
                d.normal = builder.create("back normal", {w, h, graph::TextureFormat::Rg16F});
                skipUnlessNeeded(builder, frame);
            },
            [frame](const graph::PassResources& resources, const BackFaces& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.normal);
                attachments.depth = resources.texture(d.depth);
                frame.gl->framebuffers->bind(attachments);
                frame.gl->setViewport(frame.plan.width, frame.plan.height);
                const float far = 1.0f;
                const float zero[4] = {0, 0, 0, 0};
                glClearBufferfv(GL_COLOR, 0, zero);
                glClearBufferfv(GL_DEPTH, 0, &far);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glDepthMask(GL_TRUE);
                glEnable(GL_CULL_FACE);
                glCullFace(GL_FRONT);
                glFrontFace(GL_CCW);
                glUseProgram(frame.gl->programs->backDepth.get());
                const auto& characters = frame.gl->gpuScene->characters();
                for (size_t index = 0; index < characters.size(); ++index) {
                    if (!frame.plan.characters[index].visible || !readsThinEdges(frame.plan, index)) continue;
                    const GpuCharacter& character = characters[index];
                    glBindVertexArray(character.mesh.vertexArray.get());
                    const std::vector<GpuSubmesh>& submeshes = character.submeshesAt(frame.plan.characters[index].lod);
                    for (size_t s = 0; s < submeshes.size(); ++s) {
                        frame.gl->uploadObject(frame.objectBlock(index, s));
                        submeshes[s].draw();
                    }
                }
                glCullFace(GL_BACK);
                glDisable(GL_CULL_FACE);
                glDisable(GL_DEPTH_TEST);
            });
}

}  // namespace

graph::TextureHandle addThinEdgePasses(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                                       const std::vector<graph::TextureHandle>& shadowMaps, graph::TextureHandle black) {
    const BackFaces back = addBackDepthPass(graph, frame);
    return graph
        .addPass<HiddenSideData>(
            "thin edges",
            [&](graph::PassBuilder& builder, HiddenSideData& d) {
                d.gbuffer = readSurfaceTargets(builder, gbuffer);
                d.back.depth = builder.read(back.depth);
                d.back.normal = builder.read(back.normal);
                for (graph::TextureHandle map : shadowMaps) d.shadowMaps.push_back(builder.read(map));
                d.out = builder.create("hidden side", {static_cast<uint32_t>(frame.plan.width),
                                                       static_cast<uint32_t>(frame.plan.height),
                                                       graph::TextureFormat::Rgba16F});
                builder.passThrough(d.out, black);
                skipUnlessNeeded(builder, frame);
            },
            [frame](const graph::PassResources& resources, const HiddenSideData& d) {
                // Unit 0 is not sampled: depth comes from the depth key. Units 4-7 are the shadow maps.
                beginFullscreenPass(frame, resources, {{d.out}, d.gbuffer.depthStencil}, frame.gl->programs->thinEdges.get(),
                                    {{}, d.gbuffer.albedo, d.gbuffer.normalMaterial, d.gbuffer.depthKey, {}, {}, {}, {}, {},
                                     d.back.depth, d.back.normal});
                const float zero[4] = {0, 0, 0, 0};
                glClearBufferfv(GL_COLOR, 0, zero);
                bindShadowMaps(frame, resources, d.shadowMaps);
                const ScopedSssState state(frame, sssScissor(frame.plan.sss), kAnySssPixel);
                frame.gl->drawFullscreenTriangle();
            })
        .out;
}

}  // namespace dermis
