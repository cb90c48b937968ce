// The GL half of the technique registry (scene/SssTechniques.h has the rest):
// one line per technique that adds passes; and the chain that runs them all.
#include "passes/SssPasses.h"

#include <utility>

namespace dermis {

// Each technique's passes, in its own file. The d'Eon chain (technique "gaussians"): one
// blur pair per Gaussian, with extra targets (none, or the kLeanSssTargets LEAN moments)
// blurred in the same passes with the same taps: the chain packs irradiance and moments as
// halves in one RGBA32UI texture ("sss chain", started by sss init) and the accumulations
// are float targets written through multiple render targets, the moments' with one scalar
// weight per Gaussian (include/SssBlur.glsl, "EXTRA TARGETS AND ALPHA", "PACKING").
SssChain addSssGaussianChain(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                             const SssStart& start, SssChain chain);  // passes/SssGaussianPasses.cpp
// Separable SSS (Jimenez et al. 2015).
SssChain addSeparableSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                         const SssStart& start, SssChain chain);  // passes/SssSeparablePasses.cpp
// The profile sampled on a disk in one pass.
SssChain addDiskSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                    const SssStart& start, SssChain chain);  // passes/SssDiskPass.cpp

namespace {

// A technique that scatters in the lighting pass (render/LightingScatter.h)
// has no line: `sss init` gives its slots their irradiance (SssPlan: initial
// weight 1) and no pass follows.
constexpr std::pair<SssTechnique, AddSssTechniquePasses> kTechniquePasses[] = {
    {SssTechnique::Gaussians, addSssGaussianChain},
    {SssTechnique::Separable, addSeparableSss},
    {SssTechnique::Disk, addDiskSss},
};

}  // namespace

AddSssTechniquePasses sssTechniquePasses(SssTechnique technique) {
    for (const auto& [registered, add] : kTechniquePasses) {
        if (registered == technique) return add;
    }
    return nullptr;
}

SssChain addSssChain(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                     graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras,
                     graph::TextureHandle hiddenSide) {
    SssStart start = addSssInit(graph, frame, gbuffer, irradiance, extras);
    start.hiddenSide = hiddenSide;
    SssChain chain = start.accumulated;
    for (const EnumEntry<SssTechnique>& technique : kSssTechniques) {
        if (const AddSssTechniquePasses add = sssTechniquePasses(technique.value)) {
            chain = add(graph, frame, gbuffer, start, chain);
        }
    }
    return chain;
}

}  // namespace dermis
