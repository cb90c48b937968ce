#include "frame/FrameDeclaration.h"

#include "passes/AovPass.h"
#include "passes/CompositePass.h"
#include "passes/GBufferPass.h"
#include "passes/LeanSpecularPass.h"
#include "passes/LightingPass.h"
#include "passes/ShadowPass.h"
#include "passes/SkinningPass.h"
#include "passes/SkyboxPass.h"
#include "passes/SsaoPass.h"
#include "passes/SssPasses.h"
#include "passes/ThinEdgePasses.h"
#include "passes/TextureSpacePasses.h"
#include "passes/TransmittancePass.h"

namespace dermis {

void declareFrame(graph::RenderGraph& graph, const FramePlan& plan, const FrameInputs& inputs) {
    const FrameContext frame{plan, inputs.services};
    const Aov aov = plan.aov;
    const graph::TextureDesc solidDesc{1, 1, graph::TextureFormat::Rgba8};
    const graph::TextureHandle output = graph.importTexture("output", frameOutputDesc(plan), inputs.output);
    const graph::TextureHandle white = graph.importTexture("white", solidDesc, inputs.white);
    const graph::TextureHandle black = graph.importTexture("black", solidDesc, inputs.black);

    addSkinningPasses(graph, frame);
    const std::vector<graph::TextureHandle> shadowMaps = addShadowPasses(graph, frame, inputs.shadowMaps);
    const GBuffer gbuffer = addGBufferPass(graph, frame);
    const graph::TextureHandle ambientOcclusion = addSsaoPasses(graph, frame, gbuffer, white);
    const Lighting lighting = addLightingPass(graph, frame, gbuffer, shadowMaps, ambientOcclusion, gbuffer.hasLean());

    if (aovReadsSss(aov, gbuffer.hasLean())) {
        const graph::TextureHandle hiddenSide = addThinEdgePasses(graph, frame, gbuffer, shadowMaps, black);
        graph::TextureHandle diffuse;
        LeanShading lean;
        if (plan.textureSpace) {
            // Characters texture space cannot run (plan/TsPlan.h) get the
            // screen-space chain, whose result the accumulation starts from.
            // The transmitted light goes into the gathered light, unblurred
            // (include/Transmittance.glsl), unless the TSM carries it; then
            // only the chain's characters take it, before their blur.
            const bool tsmTransmits = plan.scene->settings.ts.tsm;
            graph::TextureHandle base = lighting.irradiance;
            if (plan.ts.anyVisibleFallback()) {
                const graph::TextureHandle irradiance =
                    tsmTransmits ? addTransmittancePass(graph, frame, gbuffer, shadowMaps, lighting.irradiance, black)
                                 : lighting.irradiance;
                base = addSssChain(graph, frame, gbuffer, irradiance, gbuffer.leanTargets(), hiddenSide).diffuse;
            }
            diffuse = addTextureSpacePasses(graph, frame, gbuffer, shadowMaps, ambientOcclusion, lighting.irradiance, base,
                                            hiddenSide, black);
            if (!tsmTransmits) diffuse = addTransmittancePass(graph, frame, gbuffer, shadowMaps, diffuse, black);
        } else {
            const graph::TextureHandle irradiance =
                addTransmittancePass(graph, frame, gbuffer, shadowMaps, lighting.irradiance, black);
            const SssChain chain = addSssChain(graph, frame, gbuffer, irradiance, gbuffer.leanTargets(), hiddenSide);
            diffuse = chain.diffuse;
            if (gbuffer.hasLean()) lean = {chain.extras[0], chain.diffuse, lighting.visibility};
        }
        if (aov == Aov::Final || aov == Aov::Radiance) {
            const graph::TextureHandle hdr = addSkyboxPass(
                graph, frame, gbuffer, addCompositePass(graph, frame, gbuffer, diffuse, lighting.irradiance, lighting.specular, lean));
            graph.markOutput(aov == Aov::Final ? addTonemapPass(graph, frame, hdr, output)
                                               : addAovPass(graph, frame, {gbuffer, {}, {}, hdr, {}}, output));
            return;
        }
        if (aov == Aov::Specular) {
            const graph::TextureHandle specular = addLeanSpecularPass(graph, frame, gbuffer, lean, lighting.specular);
            graph.markOutput(addAovPass(graph, frame, {gbuffer, {}, specular, {}, {}}, output));
            return;
        }
        graph.markOutput(addAovPass(graph, frame, {gbuffer, diffuse, {}, {}, lighting.irradiance}, output));
        return;
    }
    AovInputs aovInputs{gbuffer, {}, lighting.specular, {}, {}};
    if (aov == Aov::Irradiance) aovInputs.component = lighting.irradiance;
    if (aov == Aov::Ao) aovInputs.component = ambientOcclusion;
    if (aov == Aov::Transmittance || aov == Aov::Thickness) {
        aovInputs.component = addTransmittancePass(graph, frame, gbuffer, shadowMaps, {}, black);
    }
    if (aovIsUvLayout(aov)) {
        aovInputs.component = addTsAovPasses(graph, frame, gbuffer, shadowMaps, ambientOcclusion, black);
    }
    graph.markOutput(addAovPass(graph, frame, aovInputs, output));
}

}  // namespace dermis
