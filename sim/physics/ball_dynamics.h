// Equations of motion of the 5-DOF ball on a deformable cloth (Kudra et al. 2016, eqs. 18-23).
//
// The friction resultant comes from a pluggable model (approximate or integral); the rolling
// resistance is always the regularized moment of eqs. 14-15. The Jacobian is computed by forward
// automatic differentiation (ceres::Jet) through the same templated right-hand side, so it is
// exact for whichever friction model is plugged in and cannot drift from the equations.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <utility>

#include "sim/physics/approximate_friction.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/integral_friction.h"
#include "sim/physics/parameters.h"

namespace billiard::physics {

using StateJacobian = Eigen::Matrix<double, 7, 7>;

// Friction models as the dynamics sees them: a templated call on the contact kinematics.
struct ApproximateFrictionModel {
  ContactParameters contact;
  template <typename T>
  FrictionResultant<T> operator()(const ContactKinematics<T>& k) const {
    return ApproximateFriction(k, contact);
  }
};

struct IntegralFrictionModel {
  IntegralFriction quadrature;
  double eps_t;
  template <typename T>
  FrictionResultant<T> operator()(const ContactKinematics<T>& k) const {
    return quadrature.Evaluate(k, eps_t);
  }
};

template <class Friction>
class BallDynamics {
 public:
  BallDynamics(const ModelParameters& p, Friction friction)
      : p_(p), friction_(std::move(friction)) {}

  // Time derivatives of (vx, vy, wx, wy, wz) from those five numbers (eqs. 21-22).
  template <typename T>
  Eigen::Matrix<T, 5, 1> Accelerations(const Eigen::Matrix<T, 5, 1>& u) const {
    const ContactParameters& c = p_.contact;
    const double g = p_.ball.gravity, r = p_.ball.radius, a = c.patch_radius, mu = c.mu;
    const ContactKinematics<T> k = ComputeContactKinematics(u[0], u[1], u[2], u[3], u[4], c, r);
    const FrictionResultant<T> f = friction_(k);
    const T mrx = 0.2 * k.ds;  // rolling resistance, eq. 15
    const T mry = -0.2 * k.dc;
    Eigen::Matrix<T, 5, 1> du;
    du[0] = -mu * g * f.tsx;
    du[1] = -mu * g * f.tsy;
    du[2] = -2.5 * g / r * (mu * f.tsy - a / r * mrx);
    du[3] = 2.5 * g / r * (mu * f.tsx + a / r * mry);
    du[4] = -2.5 * g / (r * r) * a * mu * f.ms;
    return du;
  }

  BallState Derivative(const BallState& s) const {
    BallState ds;
    ds[kX] = s[kVx];
    ds[kY] = s[kVy];
    ds.tail<5>() = Accelerations<double>(s.tail<5>());
    return ds;
  }

  // The derivative and its Jacobian with respect to the state, in one pass.
  void DerivativeAndJacobian(const BallState& s, BallState* ds, StateJacobian* jac) const {
    using Jet = ceres::Jet<double, 5>;
    Eigen::Matrix<Jet, 5, 1> u;
    for (int i = 0; i < 5; ++i) u[i] = Jet(s[kVx + i], i);
    const Eigen::Matrix<Jet, 5, 1> du = Accelerations<Jet>(u);
    jac->setZero();
    (*jac)(kX, kVx) = 1.0;
    (*jac)(kY, kVy) = 1.0;
    (*ds)[kX] = s[kVx];
    (*ds)[kY] = s[kVy];
    for (int i = 0; i < 5; ++i) {
      (*ds)[kVx + i] = du[i].a;
      jac->block<1, 5>(kVx + i, kVx) = du[i].v.transpose();
    }
  }

  const ModelParameters& parameters() const { return p_; }

 private:
  ModelParameters p_;
  Friction friction_;
};

}  // namespace billiard::physics
