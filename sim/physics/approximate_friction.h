// The approximate friction model of Kudra et al. 2016 (eq. 17, general m_T and m_M).
//
// Closed-form stand-ins for the integral model that agree with it exactly when either the linear
// or the angular slip vanishes (eq. 11) and are fitted to it in between (see contact_fit.h).
// With m = 2 the norms are evaluated without pow(), which is what makes m = 2 cheaper.
#pragma once

#include <cmath>

#include "sim/physics/contact_kinematics.h"

namespace billiard::physics {

namespace internal {

// (|vs|^m + b^m |ws|^m)^(2/m), from vs^2 = |vs|^2 and ws^2, so that it stays smooth for Jets.
template <typename T>
T MixedNormSquared(const T& vs2, const T& ws2, double b, double m) {
  using std::pow;
  if (m == 2.0) return vs2 + (b * b) * ws2;
  const T sum = pow(vs2, 0.5 * m) + pow(b, m) * pow(ws2, 0.5 * m);
  return pow(sum, 2.0 / m);
}

}  // namespace internal

template <typename T>
FrictionResultant<T> ApproximateFriction(const ContactKinematics<T>& k,
                                         const ContactParameters& c) {
  using std::sqrt;
  constexpr double kPi = 3.14159265358979323846;
  const T vs2 = k.vsx * k.vsx + k.vsy * k.vsy;
  const T ws2 = k.ws * k.ws;
  const double et2 = c.eps_t * c.eps_t;

  const T denom_t = sqrt(internal::MixedNormSquared(vs2, ws2, c.b_t, c.m_t) + et2);
  const T denom_m = sqrt(internal::MixedNormSquared(vs2, ws2, c.b_m, c.m_m) + et2);
  const double kt = 3.0 / 32.0 * kPi * c.b_t;  // b_T c_{0,1,1} / d_s  (eq. 12)
  const double km = 3.0 / 16.0 * kPi * c.b_m;  // b_M c_{0,0,-1}       (eq. 12)

  FrictionResultant<T> f;
  f.tsx = (k.vsx - kt * k.ds * k.ws) / denom_t;
  f.tsy = (k.vsy + kt * k.dc * k.ws) / denom_t;
  f.ms = (km * k.ws - 0.2 * k.ds * k.vsx + 0.2 * k.dc * k.vsy) / denom_m;
  return f;
}

}  // namespace billiard::physics
