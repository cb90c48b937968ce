#include "passes/ShadowPass.h"

#include <string>

namespace dermis {
namespace {

struct ShadowData {
    graph::TextureHandle depthM;
    graph::TextureHandle zBuffer;
};

}  // namespace

std::vector<graph::TextureHandle> addShadowPasses(graph::RenderGraph& graph, const FrameContext& frame,
                                                  const std::vector<graph::BackendTexture>& maps) {
    std::vector<graph::TextureHandle> handles;
    for (size_t slot = 0; slot < frame.plan.shadows.size(); ++slot) {
        const ShadowSlotPlan& shadow = frame.plan.shadows[slot];
        const graph::TextureDesc desc = shadow.desc;
        const graph::TextureHandle imported =
            graph.importTexture("shadow map " + std::to_string(slot), desc, slot < maps.size() ? maps[slot] : 0);

        const ShadowData& data = graph.addPass<ShadowData>(
            shadow.passName,
            [&](graph::PassBuilder& builder, ShadowData& d) {
                d.depthM = builder.write(imported);
                d.zBuffer = builder.create("shadow z " + std::to_string(slot),
                                           {desc.width, desc.height, graph::TextureFormat::Depth32F});
                builder.skipIf(shadow.current, "light and casters unchanged since the cached map");
                builder.skipIf(shadow.casters.kept.empty(), "no character on screen to receive its shadow");
            },
            [frame, desc, lightIndex = shadow.light, casters = shadow.casters.kept](const graph::PassResources& resources,
                                                                                   const ShadowData& d) {
                // A point light's map is a 3x2 atlas of cube faces (plan/LightSetup.h): each caster is drawn once per face.
                const bool cube = frame.plan.lights.block.lights[lightIndex].cubeShadow > 0.5f;
                const int faces = cube ? 6 : 1;
                const int faceSize = cube ? static_cast<int>(desc.height) / 2 : 0;
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.depthM);
                attachments.depth = resources.texture(d.zBuffer);
                frame.gl->framebuffers->bind(attachments);
                frame.gl->setViewport(static_cast<int>(desc.width), static_cast<int>(desc.height));
                const float farClear[4] = {1e30f, 0.0f, 0.0f, 0.0f};
                glClearBufferfv(GL_COLOR, 0, farClear);
                glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glDepthMask(GL_TRUE);
                glDisable(GL_CULL_FACE);  // thin ears need both faces in the map
                glUseProgram(frame.gl->programs->shadow.get());
                const auto& characters = frame.gl->gpuScene->characters();
                for (int face = 0; face < faces; ++face) {
                    if (cube) glViewport(face % 3 * faceSize, face / 3 * faceSize, faceSize, faceSize);
                    for (int caster : casters) {
                        const auto index = static_cast<size_t>(caster);
                        const GpuCharacter& character = characters[index];
                        gpu::ObjectBlock block = frame.objectBlock(index);
                        block.lightIndex = float(lightIndex);
                        block.cubeFace = float(face);
                        frame.gl->uploadObject(block);
                        glBindVertexArray(character.mesh.vertexArray.get());
                        character.wholeMeshAt(frame.plan.characters[index].lod).draw();
                    }
                }
                glDisable(GL_DEPTH_TEST);
            });
        handles.push_back(data.depthM);
    }
    return handles;
}

}  // namespace dermis
