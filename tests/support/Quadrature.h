#pragma once
// Numerical integration for the profile tests.

#include <functional>

namespace dermis::quadrature {

// Composite Simpson's rule on [a, b] with an even number of intervals.
inline double simpson(const std::function<double(double)>& f, double a, double b, int intervals) {
    const double h = (b - a) / intervals;
    double sum = f(a) + f(b);
    for (int i = 1; i < intervals; ++i) sum += f(a + i * h) * (i % 2 == 1 ? 4.0 : 2.0);
    return sum * h / 3.0;
}

}  // namespace dermis::quadrature
