#include "passes/ShadowPass.h"

#include <string>

namespace dermis {
namespace {

struct ShadowData {
    graph::TextureHandle depthM;
    graph::TextureHandle zBuffer;
};

std::string lightLabel(const FrameContext& frame, int lightIndex) {
    return "shadow:light" + std::to_string(lightIndex) + (frame.scene->lights[static_cast<size_t>(lightIndex)].type ==
                                                                  LightType::Directional
                                                              ? "(dir)"
                                                              : "(spot)");
}

}  // namespace

std::vector<graph::TextureHandle> addShadowPasses(graph::RenderGraph& graph, FrameContext& frame, ShadowCache& cache) {
    std::vector<graph::TextureHandle> maps;
    const int mapSize = frame.scene->settings.shadow.mapSize;
    std::vector<glm::mat4> casters;
    for (const GpuCharacter& c : frame.gpuScene->characters()) casters.push_back(c.worldFromObject);

    for (size_t slot = 0; slot < frame.lights.shadowedLights.size(); ++slot) {
        const int lightIndex = frame.lights.shadowedLights[slot];
        ShadowCache::Slot& cached = cache.slot(static_cast<int>(slot), mapSize);
        std::vector<float> key = ShadowCache::makeKey(frame.lights.block.lights[lightIndex], casters);
        const bool current = cache.isCurrent(static_cast<int>(slot), key);
        const graph::TextureHandle imported =
            graph.importTexture("shadow map " + std::to_string(slot), cached.desc, cached.depthM.get());

        const ShadowData& data = graph.addPass<ShadowData>(
            lightLabel(frame, lightIndex),
            [&](graph::PassBuilder& builder, ShadowData& d) {
                d.depthM = builder.write(imported);
                d.zBuffer = builder.create("shadow z " + std::to_string(slot),
                                           {cached.desc.width, cached.desc.height, graph::TextureFormat::Depth32F});
                builder.skipIf(current, "light and casters unchanged since the cached map");
            },
            [&frame, &cached, lightIndex, key = std::move(key)](const graph::PassResources& resources,
                                                                const ShadowData& d) {
                gl::Attachments attachments;
                attachments.colour[0] = resources.texture(d.depthM);
                attachments.depth = resources.texture(d.zBuffer);
                frame.framebuffers->bind(attachments);
                frame.setViewport(static_cast<int>(cached.desc.width), static_cast<int>(cached.desc.height));
                const float farClear[4] = {1e30f, 0.0f, 0.0f, 0.0f};
                glClearBufferfv(GL_COLOR, 0, farClear);
                glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                glDepthMask(GL_TRUE);
                glDisable(GL_CULL_FACE);  // thin ears need both faces in the map
                glUseProgram(frame.programs->shadow.get());
                const auto& characters = frame.gpuScene->characters();
                for (size_t index = 0; index < characters.size(); ++index) {
                    const GpuCharacter& character = characters[index];
                    gpu::ObjectBlock block = frame.objectBlock(index);
                    block.mapping.y = float(lightIndex);
                    frame.uploadObject(block);
                    glBindVertexArray(character.mesh.vertexArray.get());
                    glDrawElements(GL_TRIANGLES, character.mesh.indexCount, GL_UNSIGNED_INT, nullptr);
                }
                glDisable(GL_DEPTH_TEST);
                cached.key = key;
                cached.valid = true;
            });
        maps.push_back(data.depthM);
    }
    return maps;
}

}  // namespace dermis
