#include "passes/GBufferPass.h"

#include "plan/BackFaceCulling.h"

namespace dermis {

GBuffer addGBufferPass(graph::RenderGraph& graph, const FrameContext& frame) {
    const auto w = static_cast<uint32_t>(frame.plan.width);
    const auto h = static_cast<uint32_t>(frame.plan.height);
    return graph.addPass<GBuffer>(
        "gbuffer",
        [&](graph::PassBuilder& builder, GBuffer& g) {
            g.depthStencil = builder.create("depth", {w, h, graph::TextureFormat::Depth24Stencil8});
            // Half floats: 2^-11 relative (0.05%), where 8-bit sRGB lost up to 0.8% at albedo 0.5; the id
            // k / 255 reads back as k (aov.frag, lighting.frag round it) with an error 50x below half a step.
            g.albedo = builder.create("albedo", {w, h, graph::TextureFormat::Rgba16F});
            g.normalMaterial = builder.create("normal+material", {w, h, graph::TextureFormat::Rgba16F});
            g.depthKey = builder.create("depth key", {w, h, graph::TextureFormat::R32UI});
            g.scatter = builder.create("scatter", {w, h, graph::TextureFormat::Rgba16F});
            if (frame.plan.lean) {
                g.leanMoments = builder.create("lean moments", {w, h, graph::TextureFormat::Rgba16F});
                g.leanCross = builder.create("lean cross moment", {w, h, graph::TextureFormat::R16F});
            }
            if (frame.plan.environment.transfer) {
                g.environment = builder.create("environment transfer", {w, h, graph::TextureFormat::Rgba16F});
            }
        },
        [frame](const graph::PassResources& resources, const GBuffer& g) {
            gl::Attachments attachments;
            attachments.colour[0] = resources.texture(g.albedo);
            attachments.colour[1] = resources.texture(g.normalMaterial);
            attachments.colour[2] = resources.texture(g.depthKey);
            attachments.colour[DERMIS_GBUFFER_SCATTER_LOCATION] = resources.texture(g.scatter);
            if (g.hasLean()) {
                attachments.colour[4] = resources.texture(g.leanMoments);
                attachments.colour[5] = resources.texture(g.leanCross);
            }
            const bool transfer = g.environment.isValid();
            const int transferTarget = g.hasLean() ? 6 : 4;
            if (transfer) attachments.colour[transferTarget] = resources.texture(g.environment);
            attachments.depth = resources.texture(g.depthStencil);
            attachments.depthHasStencil = true;
            frame.gl->framebuffers->bind(attachments);
            frame.gl->setViewport(frame.plan.width, frame.plan.height);
            const float zero[4] = {0, 0, 0, 0};
            glClearBufferfv(GL_COLOR, 0, zero);
            glClearBufferfv(GL_COLOR, 1, zero);
            const GLuint backgroundKey[4] = {DERMIS_BACKGROUND_KEY, 0, 0, 0};
            glClearBufferuiv(GL_COLOR, 2, backgroundKey);
            glClearBufferfv(GL_COLOR, DERMIS_GBUFFER_SCATTER_LOCATION, zero);
            if (g.hasLean()) {
                glClearBufferfv(GL_COLOR, 4, zero);
                glClearBufferfv(GL_COLOR, 5, zero);
            }
            if (transfer) glClearBufferfv(GL_COLOR, transferTarget, zero);
            glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glDepthMask(GL_TRUE);
            glEnable(GL_STENCIL_TEST);
            glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
            glStencilMask(0xFF);
            glCullFace(GL_BACK);
            glFrontFace(GL_CCW);
            const Programs& programs = *frame.gl->programs;
            const GBufferPrograms& gbufferPrograms = g.hasLean() ? (transfer ? programs.gbufferLeanTransfer : programs.gbufferLean)
                                                                 : (transfer ? programs.gbufferTransfer : programs.gbuffer);
            const auto& characters = frame.gl->gpuScene->characters();
            for (size_t index = 0; index < characters.size(); ++index) {
                if (!frame.plan.characters[index].visible) continue;  // off screen (CharacterPlacement::culledBecause)
                const GpuCharacter& character = characters[index];
                const bool frontOnly = frame.plan.scene->settings.cullBackFaces &&
                                       mayCullBackFaces(character.closedOutward, frame.plan.characters[index], frame.plan.view);
                if (frontOnly) {
                    glEnable(GL_CULL_FACE);
                } else {
                    glDisable(GL_CULL_FACE);
                }
                glUseProgram(gbufferPrograms.get(character.mesh.vertexColours));
                glBindVertexArray(character.mesh.vertexArray.get());
                const int lod = frame.plan.characters[index].lod;
                const std::vector<GpuSubmesh>& submeshes = character.submeshesAt(lod);
                for (size_t s = 0; s < submeshes.size(); ++s) {
                    const GpuSubmesh& submesh = submeshes[s];
                    const GpuMaterial& material = character.material(submesh.material);
                    frame.gl->uploadObject(frame.objectBlock(index, s));
                    glStencilFunc(GL_ALWAYS, frame.plan.sss.slotOf(index, s), 0xFF);
                    bindMaterialMaps(material);
                    // A level of detail reads its own normal (and LEAN) maps: the full mesh's normals in its frame.
                    const GpuNormalMaps* levelMaps = character.lodNormalMapsAt(lod, submesh.material);
                    if (levelMaps) glBindTextureUnit(1, levelMaps->normalMap.get());
                    glBindTextureUnit(2, (levelMaps ? levelMaps->leanMap1 : material.leanMap1).get());
                    glBindTextureUnit(3, (levelMaps ? levelMaps->leanMap2 : material.leanMap2).get());
                    glBindTextureUnit(DERMIS_UNIT_SCATTER_MAP, material.scatterMap.get());
                    glBindTextureUnit(DERMIS_UNIT_THICKNESS_MAP, material.thicknessMap.get());
                    submesh.draw();
                }
            }
            glDisable(GL_CULL_FACE);
            glDisable(GL_STENCIL_TEST);
            glDisable(GL_DEPTH_TEST);
        });
}

GBuffer readSurfaceTargets(graph::PassBuilder& builder, const GBuffer& gbuffer) {
    GBuffer read;
    read.depthStencil = builder.read(gbuffer.depthStencil);
    read.albedo = builder.read(gbuffer.albedo);
    read.normalMaterial = builder.read(gbuffer.normalMaterial);
    read.depthKey = builder.read(gbuffer.depthKey);
    return read;
}

}  // namespace dermis
