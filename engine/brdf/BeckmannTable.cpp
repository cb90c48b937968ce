#include "brdf/BeckmannTable.h"

#include <cmath>

namespace dermis {

float beckmannPH(float nDotH, float m) {
    constexpr float kMinM = 1e-3f;
    m = std::fmax(m, kMinM);
    if (nDotH <= 1e-4f) return 0.0f;
    nDotH = std::fmin(nDotH, 1.0f);
    const double c2 = double(nDotH) * nDotH;
    const double tan2 = (1.0 - c2) / c2;
    const double m2 = double(m) * m;
    const double exponent = -tan2 / m2;
    if (exponent < -80.0) return 0.0f;  // underflows; the product is 0 in the limit
    return static_cast<float>(std::exp(exponent) / (m2 * c2 * c2));
}

float beckmannTableNDotH(int column, int size) {
    const float s = float(column) / float(size - 1);
    return 1.0f - s * s;
}

std::vector<float> makeBeckmannTable(int size) {
    std::vector<float> table(static_cast<size_t>(size) * static_cast<size_t>(size));
    for (int y = 0; y < size; ++y) {
        const float m = float(y) / float(size - 1);
        for (int x = 0; x < size; ++x) {
            const float nDotH = beckmannTableNDotH(x, size);
            table[static_cast<size_t>(y) * static_cast<size_t>(size) + static_cast<size_t>(x)] = beckmannPH(nDotH, m);
        }
    }
    return table;
}

}  // namespace dermis
