// The GL half of the technique registry (scene/SssTechniques.h has the rest):
// one line per technique, its passes; and the chain that runs them all.
#include "passes/SssPasses.h"

#include <array>
#include <utility>

namespace dermis {
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
