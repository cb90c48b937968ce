#pragma once
// Which pose each animated character's GPU vertex buffer holds, across
// frames: the frame plan's characters whose pose has not changed since their
// skinning pass last ran (and which then wrote the UV derivatives, if this
// frame's texture-space passes draw them) are marked current, and their pass
// is skipped. No GL, like plan/ShadowCache.h.

#include "graph/RenderGraph.h"
#include "plan/FramePlan.h"

#include <vector>

namespace dermis {

class PoseCache {
public:
    // Sets CharacterPlacement::poseCurrent for every animated character.
    void markCurrent(FramePlan& plan) const;
    // After the frame's graph ran: the characters whose skinning pass executed hold their plan's pose.
    void record(const FramePlan& plan, const graph::RenderGraph& graph);

private:
    struct Written {
        RigPose pose;  // an empty palette = nothing written yet
        bool derivatives = false;
        bool transfer = false;  // the environment's transfer was turned with it
    };
    std::vector<Written> mWritten;  // per character
};

}  // namespace dermis
