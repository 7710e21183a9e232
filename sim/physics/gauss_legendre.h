// Gauss-Legendre nodes and weights on [-1, 1].
#pragma once

#include <vector>

namespace billiard::physics {

struct QuadratureRule {
  std::vector<double> nodes;
  std::vector<double> weights;
};

// The n-point rule (n >= 1), exact for polynomials of degree 2n - 1. Nodes ascend.
QuadratureRule GaussLegendre(int n);

}  // namespace billiard::physics
