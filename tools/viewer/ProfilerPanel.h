#pragma once
// The live profiler: every pass of the latest frame with its GPU time now,
// its average over the history, a graph of that history, and its CPU time;
// culled passes are greyed with the graph's reason; the frame total below.
// With A/B on, one tab per side.

#include "viewer/PassHistory.h"

#include <string>

namespace dermis::viewer {

struct ProfiledSide {
    const char* label;  // "A", "B"
    const PassHistory* history;
};

// `renderer` and `size` describe the GL and the frame for the header line;
// `wallMs` is the viewer's measured time per frame (UI included).
void profilerPanel(const std::vector<ProfiledSide>& sides, const std::string& renderer, int width, int height,
                   double wallMs, bool& clearRequested);

}  // namespace dermis::viewer
