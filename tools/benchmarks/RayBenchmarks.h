#pragma once
// Embree against the in-house BVH on the CPU reference's rays (RayBenchmarks.cpp).

namespace dermis::bench {

// Prints the ray tracers' table (after the run).
void printRaySummary();

}  // namespace dermis::bench
