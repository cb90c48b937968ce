#include "frame/IrradianceCapture.h"

#include "passes/GBufferPass.h"
#include "passes/ShadowPass.h"
#include "passes/SkinningPass.h"
#include "passes/SsaoPass.h"
#include "passes/TsPassSteps.h"

namespace dermis {
namespace {

struct ReadBackData {
    graph::TextureHandle irradiance;
};

}  // namespace

void declareIrradianceCapture(graph::RenderGraph& graph, const FramePlan& plan, const FrameInputs& inputs,
                              std::vector<Image>& images) {
    const FrameContext frame{plan, inputs.services};
    const graph::TextureDesc solidDesc{1, 1, graph::TextureFormat::Rgba8};
    const graph::TextureHandle white = graph.importTexture("white", solidDesc, inputs.white);
    const graph::TextureHandle black = graph.importTexture("black", solidDesc, inputs.black);
    addSkinningPasses(graph, frame);
    const std::vector<graph::TextureHandle> shadowMaps = addShadowPasses(graph, frame, inputs.shadowMaps);
    const GBuffer gbuffer = addGBufferPass(graph, frame);
    const graph::TextureHandle ambientOcclusion = addSsaoPasses(graph, frame, gbuffer, white);
    images.assign(plan.scene->characters.size(), Image{});
    for (const TsCharacterPlan& character : plan.ts.characters) {
        const graph::TextureHandle tsm = addTsmPass(graph, frame, character, black);
        const graph::TextureHandle irradiance =
            addIrradiancePass(graph, frame, character, gbuffer, shadowMaps, ambientOcclusion, tsm, BuriedTexels::Lit);
        Image* image = &images[static_cast<size_t>(character.character)];
        graph.addPass<ReadBackData>(
            tsPassName(character, "read back"),
            [&](graph::PassBuilder& builder, ReadBackData& d) {
                d.irradiance = builder.read(irradiance);
                builder.sideEffect();
            },
            [image, side = character.size](const graph::PassResources& resources, const ReadBackData& d) {
                image->width = side;
                image->height = side;
                image->colourSpace = ColourSpace::Linear;
                image->texels.assign(static_cast<size_t>(side) * static_cast<size_t>(side), glm::vec4(0.0f));
                // GL's row 0 is texel row 0, v = 0.5 / side: the rows stay as they are.
                glGetTextureImage(resources.texture(d.irradiance), 0, GL_RGBA, GL_FLOAT,
                                  static_cast<GLsizei>(image->texels.size() * sizeof(glm::vec4)), image->texels.data());
            });
    }
}

}  // namespace dermis
