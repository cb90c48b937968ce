#pragma once
// Vila Verde 2015's three variants' frame cost (LeanBenchmarks.cpp).

namespace dermis::bench {

// Prints the LCB, LBB and full-moment LBB frames over the C frame, and the per-pass table (after the run).
void printLeanSummary();

}  // namespace dermis::bench
