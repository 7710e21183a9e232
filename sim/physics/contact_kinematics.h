// Dimensionless contact kinematics of the ball (Kudra et al. 2016, eqs. 14, 26, 27).
//
// Velocities are divided by the patch radius a, so the friction models see the slip of the
// contact patch in patch radii per second. Templated on the scalar so that the same code runs
// on doubles and on ceres::Jet (the integrators' Jacobians come from automatic differentiation).
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "sim/physics/parameters.h"

namespace billiard::physics {

template <typename T>
struct ContactKinematics {
  T vsx, vsy;  // linear sliding velocity of the patch centre, / a           (eq. 26)
  T ws;        // angular sliding velocity about the normal (= wz)
  T dc, ds;    // regularized rolling direction times d                       (eq. 14)
};

// vx, vy, wx, wy, wz: the five dynamic coordinates of the ball. Always inlined, as the rest of
// the derivative (see BallDynamics::Accelerations).
template <typename T>
EIGEN_ALWAYS_INLINE ContactKinematics<T> ComputeContactKinematics(const T& vx, const T& vy,
                                                                  const T& wx, const T& wy,
                                                                  const T& wz,
                                                                  const ContactParameters& c,
                                                                  double radius) {
  using std::sqrt;
  const double inv_a = 1.0 / c.patch_radius;
  const double radius_over_a = radius * inv_a;
  ContactKinematics<T> k;
  // Each slip is two independent products and a sum: the integrator's stages wait on this
  // derivative, so its chain of dependent operations is kept short.
  k.vsx = vx * inv_a - radius_over_a * wy;
  k.vsy = vy * inv_a + radius_over_a * wx;
  k.ws = wz;
  // The ball is rigid and the cloth deforms, so the rolling velocity is v itself (eq. 27).
  const T vrx = vx * inv_a;
  const T vry = vy * inv_a;
  const T scale = c.d / sqrt(vrx * vrx + vry * vry + c.eps_r * c.eps_r);
  k.dc = vrx * scale;
  k.ds = vry * scale;
  return k;
}

// d(vsx, vsy, ws, dc, ds) / d(vx, vy, wx, wy, wz) of ComputeContactKinematics: the slips are
// linear; the rolling direction (dc, ds) = d vr / sqrt(|vr|^2 + eps_r^2) has the derivative
// d (n^2 I - vr vr^T) / n^3 with n^2 = |vr|^2 + eps_r^2, vr = v / a.
inline Eigen::Matrix<double, 5, 5> ContactKinematicsJacobian(double vx, double vy,
                                                             const ContactParameters& c,
                                                             double radius) {
  const double inv_a = 1.0 / c.patch_radius;
  const double vrx = vx * inv_a, vry = vy * inv_a, er2 = c.eps_r * c.eps_r;
  const double n2 = vrx * vrx + vry * vry + er2;
  const double scale = c.d / (n2 * std::sqrt(n2)) * inv_a;  // d / n^3, per m/s of v
  const double cross = -scale * vrx * vry;
  Eigen::Matrix<double, 5, 5> jac;
  jac << inv_a, 0.0, 0.0, -radius * inv_a, 0.0,         //
      0.0, inv_a, radius * inv_a, 0.0, 0.0,             //
      0.0, 0.0, 0.0, 0.0, 1.0,                          //
      scale * (vry * vry + er2), cross, 0.0, 0.0, 0.0,  //
      cross, scale * (vrx * vrx + er2), 0.0, 0.0, 0.0;
  return jac;
}

// The friction resultant of Kudra et al. 2016 with its sign convention: the force on the ball is
// -mu N (Tsx, Tsy) and the moment about the normal is -a mu N Ms.
template <typename T>
struct FrictionResultant {
  T tsx, tsy, ms;
};

}  // namespace billiard::physics
