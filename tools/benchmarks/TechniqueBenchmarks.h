#pragma once
// What each screen-space SSS technique costs against the d'Eon chain, and what
// it gives up (TechniqueBenchmarks.cpp).

namespace dermis::bench {

// Prints the technique benchmark's table (after the run).
void printTechniqueSummary();

}  // namespace dermis::bench
