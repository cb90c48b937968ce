// The GL half of the technique registry (scene/SssTechniques.h has the rest):
// one line per technique, its passes; and the chain that runs them all.
#include "passes/SssPasses.h"

#include <array>
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

// Pre-integrated skin shading scatters in the lighting pass (passes/LightingPass.cpp,
// shaders/include/PreintegratedSkin.glsl): `sss init` gives its slots their
// irradiance (SssPlan: initial weight 1) and no pass follows.
SssChain addNoPasses(graph::RenderGraph&, const FrameContext&, const GBuffer&, const SssStart&, SssChain chain) {
    return chain;
}

constexpr std::array<std::pair<SssTechnique, AddSssTechniquePasses>, kSssTechniques.size()> kTechniquePasses{{
    {SssTechnique::Gaussians, addSssGaussianChain},
    {SssTechnique::Separable, addSeparableSss},
    {SssTechnique::Disk, addDiskSss},
    {SssTechnique::Preintegrated, addNoPasses},
}};

constexpr bool listedInTableOrder() {
    for (size_t i = 0; i < kTechniquePasses.size(); ++i) {
        if (kTechniquePasses[i].first != kSssTechniques.begin()[i].value) return false;
    }
    return true;
}
static_assert(listedInTableOrder(), "one line per technique, in kSssTechniques' order");

}  // namespace

AddSssTechniquePasses sssTechniquePasses(SssTechnique technique) {
    for (const auto& [registered, add] : kTechniquePasses) {
        if (registered == technique) return add;
    }
    return addNoPasses;
}

SssChain addSssChain(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                     graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras) {
    const SssStart start = addSssInit(graph, frame, gbuffer, irradiance, extras);
    SssChain chain = start.accumulated;
    for (const EnumEntry<SssTechnique>& technique : kSssTechniques) {
        chain = sssTechniquePasses(technique.value)(graph, frame, gbuffer, start, chain);
    }
    return chain;
}

}  // namespace dermis
