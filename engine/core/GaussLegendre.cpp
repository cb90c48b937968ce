#include "core/GaussLegendre.h"

#include <cmath>

namespace dermis {

GaussLegendre makeGaussLegendre(int n) {
    constexpr double kPi = 3.14159265358979323846;
    GaussLegendre rule;
    for (int i = 0; i < n; ++i) {
        double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int iteration = 0; iteration < 100; ++iteration) {
            double p0 = 1.0, p1 = z;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (z * p1 - p0) / (z * z - 1.0);
            const double step = p1 / derivative;
            z -= step;
            if (std::fabs(step) < 1e-15) break;
        }
        rule.nodes.push_back(z);
        rule.weights.push_back(2.0 / ((1.0 - z * z) * derivative * derivative));
    }
    return rule;
}

}  // namespace dermis
