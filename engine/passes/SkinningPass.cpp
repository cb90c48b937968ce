#include "passes/SkinningPass.h"

#include <algorithm>

namespace dermis {
namespace {

struct SkinningData {};

void skin(const FrameContext& frame, size_t index) {
    const CharacterPlacement& placement = frame.plan.characters[index];
    const GpuCharacter& character = frame.gl->gpuScene->characters()[index];
    const GpuRig& rig = character.rig;
    glNamedBufferSubData(rig.palette.get(), 0, static_cast<GLsizeiptr>(placement.pose.palette.size() * sizeof(glm::mat4)),
                         placement.pose.palette.data());
    if (!placement.pose.morphWeights.empty())
        glNamedBufferSubData(rig.morphWeights.get(), 0,
                             static_cast<GLsizeiptr>(placement.pose.morphWeights.size() * sizeof(float)),
                             placement.pose.morphWeights.data());
    gpu::SkinningBlock block{};
    // The derivatives only for a character texture space draws (render/TsMeshes.h reads them).
    block.vertexCount = rig.vertexCount;
    block.morphSlots = rig.morphSlots;
    block.writeDerivatives = textureSpaceDraws(frame.plan, index) ? 1 : 0;
    frame.gl->uploadPassBlock(&block, sizeof block);
    const std::pair<GLuint, GLuint> buffers[] = {
        {DERMIS_BINDING_SKIN_SOURCE, rig.source.get()},       {DERMIS_BINDING_SKIN_INFLUENCES, rig.influences.get()},
        {DERMIS_BINDING_SKIN_MORPHS, rig.morphDeltas.get()},  {DERMIS_BINDING_SKIN_PALETTE, rig.palette.get()},
        {DERMIS_BINDING_SKIN_MORPH_WEIGHTS, rig.morphWeights.get()},
        {DERMIS_BINDING_SKIN_OUTPUT, character.mesh.vertexBuffer.get()},
        {DERMIS_BINDING_SKIN_DERIVATIVES, rig.derivatives.get()}};
    for (const auto& [binding, buffer] : buffers) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
    glUseProgram(frame.gl->programs->skinning.get());
    const auto groups = static_cast<GLuint>((rig.vertexCount + DERMIS_SKINNING_GROUP_SIZE - 1) / DERMIS_SKINNING_GROUP_SIZE);
    // The passes after it read the buffer as vertex attributes.
    frame.gl->dispatchCompute(groups, GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    // The environment's transfer turns with the skinning (shaders/transfer_rotate.comp).
    const GLuint posedTransfer = frame.gl->environment ? frame.gl->environment->posedTransfer(index) : 0;
    if (frame.plan.environment.transfer && posedTransfer != 0) {
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DERMIS_BINDING_SKIN_SOURCE, frame.gl->environment->restTransfer(index));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, DERMIS_BINDING_SKIN_OUTPUT, posedTransfer);
        glUseProgram(frame.gl->programs->transferRotate.get());
        frame.gl->dispatchCompute(groups, GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    }
}

// Some pass draws the character this frame: the G-buffer (it is on screen) or
// a shadow map that is redrawn and keeps it as a caster.
bool drawnThisFrame(const FramePlan& plan, size_t index) {
    if (plan.characters[index].visible) return true;
    for (const ShadowSlotPlan& shadow : plan.shadows) {
        if (shadow.current) continue;
        if (std::find(shadow.casters.kept.begin(), shadow.casters.kept.end(), static_cast<int>(index)) != shadow.casters.kept.end())
            return true;
    }
    return false;
}

}  // namespace

void addSkinningPasses(graph::RenderGraph& graph, const FrameContext& frame) {
    for (size_t index = 0; index < frame.plan.characters.size(); ++index) {
        const CharacterPlacement& placement = frame.plan.characters[index];
        if (!placement.animated) continue;
        graph.addPass<SkinningData>(
            placement.skinPassName,
            [&](graph::PassBuilder& builder, SkinningData&) {
                builder.sideEffect();
                builder.skipIf(placement.poseCurrent, "the vertex buffer holds this pose already");
                builder.skipIf(!drawnThisFrame(frame.plan, index), "off screen, and no shadow map redrawn this frame holds it");
            },
            [frame, index](const graph::PassResources&, const SkinningData&) { skin(frame, index); });
    }
}

}  // namespace dermis
