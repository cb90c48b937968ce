#include "passes/SssPasses.h"

namespace dermis {

// Not yet written: the separable technique runs the d'Eon chain until its passes land.
SssChain addSeparableSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer,
                        graph::TextureHandle irradiance, const std::vector<graph::TextureHandle>& extras) {
    return addSssGaussianChain(graph, frame, gbuffer, irradiance, extras);
}

}  // namespace dermis
