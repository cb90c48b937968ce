#pragma once
// What recording every frame's timings costs (ProfilingBenchmarks.cpp).

namespace dermis::bench {

// Prints the profiling benchmark's table (after the run).
void printProfilingSummary();

}  // namespace dermis::bench
