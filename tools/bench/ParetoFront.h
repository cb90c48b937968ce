#pragma once
// Pareto fronts of time against error (`dermis bench`). No GL.

#include <vector>

namespace dermis::bench {

struct CostError {
    double costMs = 0.0;
    double error = 0.0;
};

// onFront[i] is true when no other point is at most as costly and at most as
// wrong, and strictly better in one of the two. Points with a non-finite cost
// or error are never on the front (and dominate nothing). Of exact
// duplicates, all are on the front.
std::vector<bool> paretoFront(const std::vector<CostError>& points);

}  // namespace dermis::bench
