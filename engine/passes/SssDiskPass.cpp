#include "passes/SssPasses.h"

namespace dermis {

// Not yet written: the disk technique's slots run the d'Eon chain until its passes land.
SssChain addDiskSss(graph::RenderGraph& graph, const FrameContext& frame, const GBuffer& gbuffer, const SssStart& start,
                   SssChain chain) {
    return addSssGaussianChain(graph, frame, gbuffer, start, chain, SssTechnique::Disk);
}

}  // namespace dermis
