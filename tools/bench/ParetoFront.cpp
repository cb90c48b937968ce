#include "bench/ParetoFront.h"

#include <cmath>

namespace dermis::bench {

namespace {

bool finite(const CostError& p) { return std::isfinite(p.costMs) && std::isfinite(p.error); }

bool dominates(const CostError& a, const CostError& b) {
    return a.costMs <= b.costMs && a.error <= b.error && (a.costMs < b.costMs || a.error < b.error);
}

}  // namespace

std::vector<bool> paretoFront(const std::vector<CostError>& points) {
    // Quadratic, which is fine for the few hundred configurations of a sweep.
    std::vector<bool> onFront(points.size(), false);
    for (size_t i = 0; i < points.size(); ++i) {
        if (!finite(points[i])) continue;
        bool dominated = false;
        for (size_t j = 0; j < points.size() && !dominated; ++j) {
            dominated = j != i && finite(points[j]) && dominates(points[j], points[i]);
        }
        onFront[i] = !dominated;
    }
    return onFront;
}

}  // namespace dermis::bench
