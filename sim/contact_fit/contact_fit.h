// Least-squares fit of the approximate friction model (eq. 17) to the integral model (eq. 5),
// as in Kudra et al. 2016, section 2.3:
//   F_T(b_T, m_T) = int_D (Tsx - Tsx^I)^2 + (Tsy - Tsy^I)^2 dD,
//   F_M(b_M, m_M) = int_D (Ms - Ms^I)^2 dD
// over D = {0 <= d <= 1, 0 <= gamma <= pi, -pi/2 <= theta_s <= pi/2} with phi_s = 0, i.e. the slip
// vs = (cos theta_s, 0), ws = sin theta_s and the rolling direction (d cos gamma, d sin gamma).
// The integrals over D use a tensor Gauss-Legendre grid; the two fits are independent Ceres
// problems in two unknowns each.
//
// Module: billiard::contact_fit, the one user of Ceres' solver among the physics. Includes the
// physics (sim/physics/) and nothing else of the project.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "sim/physics/integral_friction.h"

namespace billiard::contact_fit {

struct ContactFitOptions {
  std::optional<double> fixed_m;  // fit b only, with m_T = m_M = fixed_m
  int nodes_d = 6;                // Gauss-Legendre nodes over d, gamma and theta_s
  int nodes_gamma = 12;
  int nodes_theta = 32;
  double quadrature_tolerance = 1e-6;  // of the integral model at each node
};

struct ContactFit {
  double b_t = 0.0, m_t = 0.0, b_m = 0.0, m_m = 0.0;
  double cost_t = 0.0, cost_m = 0.0;  // F_T and F_M at the optimum
  double cost() const { return cost_t + cost_m; }
  int samples = 0;                           // grid nodes in D
  physics::CalibratedQuadrature quadrature;  // of the integral model used
};

// progress, when given, receives one-line human-readable updates.
ContactFit FitContactApproximation(const ContactFitOptions& options,
                                   const std::function<void(const std::string&)>& progress = {});

}  // namespace billiard::contact_fit
