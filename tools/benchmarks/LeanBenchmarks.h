#pragma once
// Vila Verde 2015's three variants' frame cost (LeanBenchmarks.cpp).

namespace dermis::bench {

// Prints the LBB / C and LCB / C frame ratios and the per-pass table (after the run).
void printLeanSummary();

}  // namespace dermis::bench
