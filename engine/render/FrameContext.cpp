#include "render/FrameContext.h"

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>

#include <cassert>

namespace dermis {

void FrameServices::drawFullscreenTriangle() const {
    glBindVertexArray(emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FrameServices::drawRegions(const std::vector<glm::ivec4>& regions) const {
    if (regions.empty()) {
        drawFullscreenTriangle();
        return;
    }
    gpu::ScreenRegionsBlock block{};
    const size_t count = std::min<size_t>(regions.size(), DERMIS_MAX_SCREEN_REGIONS);
    std::copy_n(regions.begin(), count, block.regions);
    glNamedBufferSubData(regionUniforms, 0, static_cast<GLsizeiptr>(count * sizeof(glm::ivec4)), block.regions);
    glBindVertexArray(emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0 + 3, static_cast<GLsizei>(6 * count));
}

void FrameServices::dispatchCompute(GLuint groups, GLbitfield barriers) const {
    glDispatchCompute(groups, 1, 1);
    glMemoryBarrier(barriers);
    // llvmpipe leaves the GL_TIME_ELAPSED query after one that held only a
    // dispatch without a start time (the next pass then reports the time
    // since boot); a clear inside this pass's query gives it one. Clearing
    // the 1x1 white input to white changes nothing.
    gl::Attachments attachments;
    attachments.colour[0] = whiteTexture;
    framebuffers->bind(attachments);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glClearBufferfv(GL_COLOR, 0, white);
}

void FrameServices::uploadObject(const gpu::ObjectBlock& block) const {
    glNamedBufferSubData(objectUniforms, 0, sizeof block, &block);
}

void FrameServices::uploadPassBlock(const void* data, size_t size) const {
    assert(size <= kMaxPassBlockBytes);
    glNamedBufferSubData(passUniforms, 0, static_cast<GLsizeiptr>(size), data);
}

gpu::ObjectBlock FrameContext::objectBlock(size_t characterIndex) const {
    const glm::mat4& worldFromObject = plan.characters[characterIndex].worldFromObject;
    gpu::ObjectBlock block{};
    block.worldFromObject = worldFromObject;
    block.normalWorldFromObject = glm::inverseTranspose(worldFromObject);
    block.objectId = float(characterIndex + 1);
    if (characterIndex < plan.environment.objectSh.size()) {
        const Sh9& light = plan.environment.objectSh[characterIndex];
        for (int i = 0; i < kShCoefficients; ++i) block.environmentSh[i] = glm::vec4(light.coefficients[size_t(i)], 0.0f);
    }
    return block;
}

gpu::ObjectBlock FrameContext::objectBlock(size_t characterIndex, size_t submeshIndex) const {
    const GpuCharacter& character = gl->gpuScene->characters()[characterIndex];
    const GpuSubmesh& submesh = character.submeshes[submeshIndex];
    const GpuMaterial& maps = character.material(submesh.material);
    const Material& material = characterMaterial(plan.scene->characters[characterIndex], maps.name, maps.index);
    gpu::ObjectBlock block = objectBlock(characterIndex);
    block.albedo = material.albedo * glm::vec3(maps.baseColourFactor);
    block.roughness = material.roughness;
    block.rhoS = material.rhoS;
    block.hasAlbedoMap = maps.albedoMap.isValid() ? 1.0f : 0.0f;
    block.hasNormalMap = maps.normalMap.isValid() ? 1.0f : 0.0f;
    block.flipV = material.flipV ? 1.0f : 0.0f;
    const int roughnessSource = maps.roughnessMap.isValid()           ? DERMIS_ROUGHNESS_MAP
                                : maps.metallicRoughnessMap.isValid() ? DERMIS_ROUGHNESS_GLTF
                                                                      : DERMIS_ROUGHNESS_SCALAR;
    block.profileSlot = float(plan.sss.slotOf(characterIndex, submeshIndex));
    block.roughnessSource = float(roughnessSource);
    block.roughnessFactor = maps.roughnessFactor;
    block.hasSpecularMap = maps.specularMap.isValid() ? 1.0f : 0.0f;
    block.scatteringShare = maps.scatter >= 0.0f ? maps.scatter : material.scatter;
    block.hasScatterMap = maps.scatterMap.isValid() ? 1.0f : 0.0f;
    block.thicknessMm = maps.thicknessMm;
    block.hasThicknessMap = maps.thicknessMap.isValid() ? 1.0f : 0.0f;
    return block;
}

void bindMaterialMaps(const GpuMaterial& material) {
    glBindTextureUnit(0, material.albedoMap.get());
    glBindTextureUnit(1, material.normalMap.get());
    const GLuint roughness =
        material.roughnessMap.isValid() ? material.roughnessMap.get() : material.metallicRoughnessMap.get();
    glBindTextureUnit(DERMIS_UNIT_ROUGHNESS, roughness);
    glBindTextureUnit(DERMIS_UNIT_SPECULAR, material.specularMap.get());
}

}  // namespace dermis
