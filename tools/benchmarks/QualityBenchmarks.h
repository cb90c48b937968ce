#pragma once
// An error budget against fixed settings on a crowd at mixed distances (QualityBenchmarks.cpp).

namespace dermis::bench {

// Prints the error-budget benchmark's figures (after the run).
void printQualitySummary();

}  // namespace dermis::bench
