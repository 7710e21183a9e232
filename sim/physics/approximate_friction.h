// The approximate friction model of Kudra et al. 2016 (eq. 17, general m_T and m_M).
//
// Closed-form stand-ins for the integral model that agree with it exactly when either the linear
// or the angular slip vanishes (eq. 11) and are fitted to it in between (see contact_fit.h).
// With m = 2 the norms are evaluated without pow(), which is what makes m = 2 cheaper.
//
// Being closed-form, the model also has a hand-derived Jacobian (ApproximateFrictionAndJacobian),
// which the 5-DOF dynamics uses instead of automatic differentiation: eq. 17 is a quotient
// N / sqrt(Q + eps_t^2) of a numerator N linear in the slip and a mixed norm Q homogeneous of
// degree 2, so d/dz (N / D) = (dN/dz - (N / D) dD/dz) / D with dD/dz = (dQ/dz) / (2 D).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "sim/physics/contact_kinematics.h"

namespace billiard::physics {

namespace internal {

// (|vs|^m + b^m |ws|^m)^(2/m), from vs^2 = |vs|^2 and ws^2, so that it stays smooth for Jets.
template <typename T>
EIGEN_ALWAYS_INLINE T MixedNormSquared(const T& vs2, const T& ws2, double b, double m) {
  using std::pow;
  if (m == 2.0) return vs2 + (b * b) * ws2;
  const T sum = pow(vs2, 0.5 * m) + pow(b, m) * pow(ws2, 0.5 * m);
  return pow(sum, 2.0 / m);
}

// Q = MixedNormSquared and its partial derivatives with respect to vs^2 and ws^2.
struct MixedNormGradient {
  double value, d_vs2, d_ws2;
};

// With S = p + q, p = vs2^(m/2), q = b^m ws2^(m/2) and Q = S^(2/m):
//   dQ/d(vs2) = (Q / S) (p / vs2) and dQ/d(ws2) = (Q / S) (q / ws2).
// Where vs2 = 0 the first one multiplies dvs2 = 2 vs dvs = 0 (and tends to 0 for m > 2 anyway),
// so it is set to 0 there rather than 0/0; the same for ws2. The value is computed by the same
// operations as MixedNormSquared<double>, so that both give the same bits.
inline MixedNormGradient MixedNormSquaredAndGradient(double vs2, double ws2, double b, double m) {
  if (m == 2.0) return {vs2 + (b * b) * ws2, 1.0, b * b};
  const double p = std::pow(vs2, 0.5 * m);
  const double q = std::pow(b, m) * std::pow(ws2, 0.5 * m);
  const double sum = p + q;
  const double value = std::pow(sum, 2.0 / m);
  const double ratio = value / sum;
  return {value, vs2 > 0.0 ? ratio * (p / vs2) : 0.0, ws2 > 0.0 ? ratio * (q / ws2) : 0.0};
}

constexpr double kPi = 3.14159265358979323846;

// b_T c_{0,1,1} / d_s and b_M c_{0,0,-1} of eq. 12.
inline double TangentialSpinCoefficient(const ContactParameters& c) {
  return 3.0 / 32.0 * kPi * c.b_t;
}
inline double MomentSpinCoefficient(const ContactParameters& c) { return 3.0 / 16.0 * kPi * c.b_m; }

// Eq. 17 given its two denominators sqrt(Q_T + eps_t^2) and sqrt(Q_M + eps_t^2).
template <typename T>
EIGEN_ALWAYS_INLINE FrictionResultant<T> ResultantFromDenominators(const ContactKinematics<T>& k,
                                                                   const T& denom_t,
                                                                   const T& denom_m,
                                                                   const ContactParameters& c) {
  const double kt = TangentialSpinCoefficient(c);
  const double km = MomentSpinCoefficient(c);
  // The rolling direction (dc, ds) is the latest input (a square root and a division of its
  // own): it enters last, and the division by a denominator is a product with its reciprocal,
  // computed while the numerators wait for it.
  const T inv_t = 1.0 / denom_t;
  const T inv_m = 1.0 / denom_m;
  const T kt_ws = kt * k.ws;
  FrictionResultant<T> f;
  f.tsx = (k.vsx - k.ds * kt_ws) * inv_t;
  f.tsy = (k.vsy + k.dc * kt_ws) * inv_t;
  f.ms = (km * k.ws + 0.2 * (k.dc * k.vsy - k.ds * k.vsx)) * inv_m;
  return f;
}

}  // namespace internal

// Always inlined, as the rest of the derivative (see BallDynamics::Accelerations).
template <typename T>
EIGEN_ALWAYS_INLINE FrictionResultant<T> ApproximateFriction(const ContactKinematics<T>& k,
                                                             const ContactParameters& c) {
  using std::sqrt;
  const T vs2 = k.vsx * k.vsx + k.vsy * k.vsy;
  const T ws2 = k.ws * k.ws;
  const double et2 = c.eps_t * c.eps_t;
  const T denom_t = sqrt(internal::MixedNormSquared(vs2, ws2, c.b_t, c.m_t) + et2);
  const T denom_m = sqrt(internal::MixedNormSquared(vs2, ws2, c.b_m, c.m_m) + et2);
  return internal::ResultantFromDenominators(k, denom_t, denom_m, c);
}

// d(Tsx, Tsy, Ms) / d(vsx, vsy, ws, dc, ds): rows the resultant, columns the kinematics in the
// order of ContactKinematics.
using FrictionJacobian = Eigen::Matrix<double, 3, 5>;

// ApproximateFriction (the same bits) and its Jacobian with respect to the kinematics.
inline FrictionResultant<double> ApproximateFrictionAndJacobian(const ContactKinematics<double>& k,
                                                                const ContactParameters& c,
                                                                FrictionJacobian* jac) {
  const double vs2 = k.vsx * k.vsx + k.vsy * k.vsy;
  const double ws2 = k.ws * k.ws;
  const double et2 = c.eps_t * c.eps_t;
  const internal::MixedNormGradient qt =
      internal::MixedNormSquaredAndGradient(vs2, ws2, c.b_t, c.m_t);
  const internal::MixedNormGradient qm =
      internal::MixedNormSquaredAndGradient(vs2, ws2, c.b_m, c.m_m);
  const double denom_t = std::sqrt(qt.value + et2);
  const double denom_m = std::sqrt(qm.value + et2);
  const FrictionResultant<double> f = internal::ResultantFromDenominators(k, denom_t, denom_m, c);

  const double kt = internal::TangentialSpinCoefficient(c);
  const double km = internal::MomentSpinCoefficient(c);
  const double inv_t = 1.0 / denom_t, inv_m = 1.0 / denom_m;
  // (dD/dz) / D for D = denom_t and D = denom_m, the vs and ws parts: dQ/dvsx = 2 vsx dQ/dvs2.
  const double gv_t = qt.d_vs2 * inv_t * inv_t, gw_t = qt.d_ws2 * inv_t * inv_t;
  const double gv_m = qm.d_vs2 * inv_m * inv_m, gw_m = qm.d_ws2 * inv_m * inv_m;
  // Each row: (dN/dz) / D - (N / D) (dD/dz) / D.
  *jac << inv_t - f.tsx * k.vsx * gv_t, -f.tsx * k.vsy * gv_t,
      -kt * k.ds * inv_t - f.tsx * k.ws * gw_t, 0.0, -kt * k.ws * inv_t,
      // Tsy
      -f.tsy * k.vsx * gv_t, inv_t - f.tsy * k.vsy * gv_t, kt * k.dc * inv_t - f.tsy * k.ws * gw_t,
      kt * k.ws * inv_t, 0.0,
      // Ms
      -0.2 * k.ds * inv_m - f.ms * k.vsx * gv_m, 0.2 * k.dc * inv_m - f.ms * k.vsy * gv_m,
      km * inv_m - f.ms * k.ws * gw_m, 0.2 * k.vsy * inv_m, -0.2 * k.vsx * inv_m;
  return f;
}

}  // namespace billiard::physics
