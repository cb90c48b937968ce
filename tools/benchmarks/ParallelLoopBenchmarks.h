#pragma once
// The in-house parallel loop against oneTBB's on the reference's rays (ParallelLoopBenchmarks.cpp).

namespace dermis::bench {

// Prints the loops' table (after the run).
void printParallelLoopSummary();

}  // namespace dermis::bench
