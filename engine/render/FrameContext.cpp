#include "render/FrameContext.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace dermis {

void FrameContext::drawFullscreenTriangle() const {
    glBindVertexArray(emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

void FrameContext::uploadObject(const gpu::ObjectBlock& block) const {
    glNamedBufferSubData(objectUniforms, 0, sizeof block, &block);
}

gpu::ObjectBlock FrameContext::objectBlock(const GpuCharacter& character) const {
    const Material& material = character.source->material;
    gpu::ObjectBlock block{};
    block.worldFromObject = character.worldFromObject;
    block.normalWorldFromObject = glm::inverseTranspose(character.worldFromObject);
    block.albedoRoughness = glm::vec4(material.albedo, material.roughness);
    block.material = glm::vec4(material.rhoS, float(character.profileId), character.albedoMap.isValid() ? 1.0f : 0.0f,
                               character.normalMap.isValid() ? 1.0f : 0.0f);
    block.mapping = glm::vec4(material.flipV ? 1.0f : 0.0f, 0.0f, 0.0f, 0.0f);
    return block;
}

}  // namespace dermis
