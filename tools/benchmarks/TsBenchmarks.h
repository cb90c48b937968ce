#pragma once
// Texture-space against screen-space SSS cost (TsBenchmarks.cpp).

namespace dermis::bench {

// Prints the table of the texture-space benchmarks' medians (after the run).
void printTextureSpaceSummary();

}  // namespace dermis::bench
