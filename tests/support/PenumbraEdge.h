#pragma once
// The closed form a straight shadow edge's penumbra is tested against
// (docs/shadows.md). A light of angular radius alpha seen from a receiver (a
// disc of directions) is cut by the plane through the receiver and the
// blocker's edge; when that plane lies at angle delta from the light's centre
// direction, the visible fraction is the area of a disc segment:
//   v = 1 - (acos(t) - t sqrt(1 - t^2)) / pi,   t = clamp(sin(delta) / sin(alpha), -1, 1)
// (a flat disc: exact to O(alpha^2), 0.05% at a 5-degree light). The penumbra
// runs from t = -1 to t = 1; its 10%-90% width is what the tests compare,
// since the 0% and 100% ends are where a sampled profile is least defined.

#include <algorithm>
#include <cmath>
#include <vector>

namespace dermis::test {

// The straight-edge scene the shadow tests render (render/test_shadows.cpp,
// render/test_preintegrated_shadow.cpp): a 0.3 m floor square at y = 0 under a
// horizontal 0.2 m square blocker at kEdgeBlockerHeightM whose right edge runs
// along z at x = kEdgeBlockerXM, seen straight down from kEdgeCameraHeightM with
// a vertical field of view of kEdgeFovDeg, at kEdgeWidth x kEdgeHeight pixels.
constexpr int kEdgeWidth = 320;
constexpr int kEdgeHeight = 180;
constexpr double kEdgeFovDeg = 30.0;
constexpr double kEdgeCameraHeightM = 0.15;
constexpr double kEdgeBlockerHeightM = 0.05;
constexpr double kEdgeBlockerXM = -0.05;

inline double discSegmentVisibility(double t) {
    t = std::clamp(t, -1.0, 1.0);
    return 1.0 - (std::acos(t) - t * std::sqrt(1.0 - t * t)) / 3.14159265358979323846;
}

// The t at which discSegmentVisibility(t) = v, by bisection.
inline double discSegmentOffset(double v) {
    double lo = -1.0, hi = 1.0;
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (discSegmentVisibility(mid) < v ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Where a profile sampled at increasing xs first crosses `level` (linear
// between samples); NaN if it never does.
inline double firstCrossing(const std::vector<double>& xs, const std::vector<double>& values, double level) {
    for (size_t i = 1; i < xs.size(); ++i) {
        if ((values[i - 1] - level) * (values[i] - level) <= 0.0 && values[i] != values[i - 1]) {
            return xs[i - 1] + (level - values[i - 1]) / (values[i] - values[i - 1]) * (xs[i] - xs[i - 1]);
        }
    }
    return std::nan("");
}

// The 10%-90% width of a rising profile.
inline double width10To90(const std::vector<double>& xs, const std::vector<double>& values) {
    return firstCrossing(xs, values, 0.9) - firstCrossing(xs, values, 0.1);
}

}  // namespace dermis::test
