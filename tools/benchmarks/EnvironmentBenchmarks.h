#pragma once
// What environment light costs a frame (EnvironmentBenchmarks.cpp).

namespace dermis::bench {

// Prints the environment benchmark's table (after the run).
void printEnvironmentSummary();

}  // namespace dermis::bench
