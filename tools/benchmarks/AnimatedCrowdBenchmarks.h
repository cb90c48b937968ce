#pragma once

namespace dermis::bench {

// The table of the animatedCrowd benchmark (docs/animation.md, "Cost").
void printAnimatedCrowdSummary();

}  // namespace dermis::bench
