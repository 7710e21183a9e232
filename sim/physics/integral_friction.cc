#include "sim/physics/integral_friction.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace billiard::physics {

IntegralFriction::IntegralFriction(QuadratureOrder order)
    : order_(order),
      angular_rule_(GaussLegendre(order.angular)),
      radial_rule_(GaussLegendre(order.radial)) {
  if (order.angular < 4 || order.radial < 2) {
    throw std::invalid_argument("integral friction quadrature needs at least 4 x 2 nodes");
  }
  const double kTwoPi = 2.0 * 3.14159265358979323846;
  for (int j = 0; j < order.angular; ++j) {
    cos_periodic_.push_back(std::cos(kTwoPi * j / order.angular));
    sin_periodic_.push_back(std::sin(kTwoPi * j / order.angular));
  }
}

namespace {

// Probe states in dimensionless slip: the ICR at distances 0 ... 100 patch radii in several
// directions relative to the rolling direction, plus pure sliding and pure spin.
std::vector<ContactKinematics<double>> ProbeStates(double d) {
  std::vector<ContactKinematics<double>> probes;
  const std::array<double, 11> icr_distance = {0.0,   0.3,  0.7, 0.9, 0.97, 0.995,
                                               1.005, 1.05, 1.5, 4.0, 100.0};
  const std::array<double, 3> icr_angle = {0.0, 1.1, 2.6};
  const double gamma = 0.7;  // rolling direction
  for (double dist : icr_distance) {
    for (double angle : icr_angle) {
      for (double ws : {1.0, -3.0}) {
        const double cx = dist * std::cos(angle), cy = dist * std::sin(angle);
        // c = (-vsy, vsx) / ws  =>  vsx = ws cy, vsy = -ws cx.
        probes.push_back({ws * cy, -ws * cx, ws, d * std::cos(gamma), d * std::sin(gamma)});
      }
    }
  }
  probes.push_back({1.0, 0.5, 0.0, d * std::cos(gamma), d * std::sin(gamma)});
  probes.push_back({0.0, 0.0, 2.0, d * std::cos(gamma), d * std::sin(gamma)});
  return probes;
}

double MaxDifference(const FrictionResultant<double>& a, const FrictionResultant<double>& b) {
  return std::max({std::abs(a.tsx - b.tsx), std::abs(a.tsy - b.tsy), std::abs(a.ms - b.ms)});
}

}  // namespace

CalibratedQuadrature CalibrateQuadrature(double eps_t, double d, double tol) {
  if (!(tol > 0.0)) throw std::invalid_argument("quadrature tolerance must be positive");
  const auto probes = ProbeStates(d);
  QuadratureOrder order{16, 8};
  IntegralFriction coarse(order);
  while (order.angular <= 2048) {
    const QuadratureOrder finer_order{2 * order.angular, 2 * order.radial};
    IntegralFriction fine(finer_order);
    double error = 0.0;
    for (const auto& k : probes) {
      error = std::max(error, MaxDifference(coarse.Evaluate(k, eps_t), fine.Evaluate(k, eps_t)));
    }
    if (error <= tol) return {order, error};
    order = finer_order;
    coarse = std::move(fine);
  }
  throw std::runtime_error("integral friction: quadrature tolerance " + std::to_string(tol) +
                           " not reached with 4096 x 2048 nodes");
}

}  // namespace billiard::physics
