#include "passes/ShadowPass.h"

#include <algorithm>
#include <string>

namespace dermis {
namespace {

struct ShadowData {
    graph::TextureHandle depthM;
    graph::TextureHandle zBuffer;
};

// The map's max-depth mip chain from level 2 up to its last level
// (shaders/shadow_max.comp; level 1 is never read).
void buildMaxDepthMips(const FrameContext& frame, GLuint map, const graph::TextureDesc& desc) {
    GLint levels = 1;
    glGetTextureParameteriv(map, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glUseProgram(frame.gl->programs->shadowMax.get());
    for (int level = 2; level < levels; ++level) {
        const int finer = level == 2 ? 0 : level - 1;
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        glUniform1i(0, 1 << (level - finer));
        glUniform1i(1, finer);
        glBindTextureUnit(0, map);
        glBindImageTexture(1, map, level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
        const GLuint width = std::max(1u, desc.width >> level);
        const GLuint height = std::max(1u, desc.height >> level);
        glDispatchCompute((width + 7) / 8, (height + 7) / 8, 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindTextureUnit(0, 0);
    glBindImageTexture(1, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
}

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
            [frame, desc, lightIndex = shadow.light, casters = shadow.casters.kept,
             levels = shadow.castersDrawLevels](const graph::PassResources& resources, const ShadowData& d) {
                // A point light's map is a 3x2 atlas of cube faces (plan/LightSetup.h): each caster is drawn once per face.
                const bool cube = frame.plan.lights.block.lights[lightIndex].cubeShadow > 0.5f;
                const int faces = cube ? 6 : 1;
                const int faceSize = cube ? static_cast<int>(desc.height) / 2 : 0;
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.depthM);
                attachments.depth = resources.texture(d.zBuffer);
                frame.gl->framebuffers->bind(attachments);
                frame.gl->setViewport(static_cast<int>(desc.width), static_cast<int>(desc.height));
                const float farClear[4] = {DERMIS_SHADOW_NO_SURFACE_M, 0.0f, 0.0f, 0.0f};
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
                        character.wholeMeshAt(levels ? frame.plan.characters[index].lod : 0).draw();
                    }
                }
                glDisable(GL_DEPTH_TEST);
                // Only the transmittance reads the mips, and only a back light's map.
                if (frame.plan.lights.block.lights[lightIndex].backLight > 0.5f && !cube)
                    buildMaxDepthMips(frame, resources.texture(d.depthM), desc);
            });
        handles.push_back(data.depthM);
    }
    return handles;
}

}  // namespace dermis
