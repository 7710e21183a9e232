#include "sim/physics/gauss_legendre.h"

#include <cmath>
#include <stdexcept>

namespace billiard::physics {

QuadratureRule GaussLegendre(int n) {
  if (n < 1) throw std::invalid_argument("Gauss-Legendre rule needs at least one node");
  constexpr double kPi = 3.14159265358979323846;
  QuadratureRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  // Newton's method on P_n from Tricomi's initial guess; the roots are symmetric, so solve half.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / derivative;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
    rule.nodes[i] = -x;
    rule.nodes[n - 1 - i] = x;
    rule.weights[i] = w;
    rule.weights[n - 1 - i] = w;
  }
  return rule;
}

}  // namespace billiard::physics
