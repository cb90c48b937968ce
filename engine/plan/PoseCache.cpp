#include "plan/PoseCache.h"

namespace dermis {

void PoseCache::markCurrent(FramePlan& plan) const {
    for (size_t c = 0; c < plan.characters.size(); ++c) {
        CharacterPlacement& placement = plan.characters[c];
        if (!placement.animated || c >= mWritten.size()) continue;
        const Written& written = mWritten[c];
        placement.poseCurrent = !written.pose.palette.empty() && written.pose.palette == placement.pose.palette &&
                                written.pose.morphWeights == placement.pose.morphWeights &&
                                (written.derivatives || !textureSpaceDraws(plan, c)) &&
                                (written.transfer || !plan.environment.transfer);
    }
}

void PoseCache::record(const FramePlan& plan, const graph::RenderGraph& graph) {
    mWritten.resize(plan.characters.size());
    for (size_t c = 0; c < plan.characters.size(); ++c) {
        const CharacterPlacement& placement = plan.characters[c];
        if (placement.animated && graph.wasExecuted(placement.skinPassName))
            mWritten[c] = {placement.pose, textureSpaceDraws(plan, c), plan.environment.transfer};
    }
}

}  // namespace dermis
