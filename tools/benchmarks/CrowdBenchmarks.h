#pragma once
// A head on screen alone and with heads off screen, both modes (CrowdBenchmarks.cpp).

namespace dermis::bench {

// Prints the crowd benchmark's table (after the run).
void printCrowdSummary();

}  // namespace dermis::bench
