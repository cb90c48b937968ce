#pragma once
// Gauss-Legendre quadrature: n nodes and weights on [-1, 1] (Newton's method
// on the Legendre polynomial P_n), exact for polynomials of degree 2n - 1.

#include <vector>

namespace dermis {

struct GaussLegendre {
    std::vector<double> nodes;    // in (-1, 1), descending
    std::vector<double> weights;  // sum to 2
};

GaussLegendre makeGaussLegendre(int n);

}  // namespace dermis
