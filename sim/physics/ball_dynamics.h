// Equations of motion of the 5-DOF ball on a deformable cloth (Kudra et al. 2016, eqs. 18-23).
//
// The friction resultant comes from a pluggable model (approximate or integral); the rolling
// resistance is always the regularized moment of eqs. 14-15.
//
// The Jacobian: for a friction model with a hand-derived one (the approximate model, eq. 17) it is
// the chain rule through the kinematics (ContactKinematicsJacobian) and the friction
// (ResultantAndJacobian); the equations of motion are linear in the resultant and the rolling
// direction, so those gradients are carried through them as ceres::Jet, which takes the same
// code as the derivative and gives its bits. For the others (the integral model, whose quadrature
// has no closed-form derivative) it is forward automatic differentiation (ceres::Jet) through the
// whole templated right-hand side, exact for whichever model is plugged in;
// DerivativeAndJacobianByAutoDiff stays available to every model as the oracle of the analytic one.
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <type_traits>
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
  EIGEN_ALWAYS_INLINE FrictionResultant<T> operator()(const ContactKinematics<T>& k) const {
    return ApproximateFriction(k, contact);
  }
  FrictionResultant<double> ResultantAndJacobian(const ContactKinematics<double>& k,
                                                 FrictionJacobian* jac) const {
    return ApproximateFrictionAndJacobian(k, contact, jac);
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

// Whether a friction model has a hand-derived Jacobian, i.e. provides
//   FrictionResultant<double> ResultantAndJacobian(const ContactKinematics<double>&,
//                                                  FrictionJacobian*) const.
template <class Friction, class = void>
struct HasAnalyticJacobian : std::false_type {};
template <class Friction>
struct HasAnalyticJacobian<
    Friction,
    std::void_t<decltype(std::declval<const Friction&>().ResultantAndJacobian(
        std::declval<const ContactKinematics<double>&>(), std::declval<FrictionJacobian*>()))>>
    : std::true_type {};

template <class Friction>
class BallDynamics {
 public:
  BallDynamics(const ModelParameters& p, Friction friction)
      : p_(p), friction_(std::move(friction)) {}

  // The motion does not depend on where the ball is: RODAS4 factors only the 5x5 block of its
  // stage matrix (stage_matrix.h).
  static constexpr bool kTranslationInvariant = true;

  // Time derivatives of (vx, vy, wx, wy, wz) from those five numbers (eqs. 21-22).
  //
  // The whole derivative is inlined into its callers (EIGEN_ALWAYS_INLINE here and on the
  // kinematics and friction it calls): these templates are instantiated in every translation unit
  // that simulates, and the linker keeps one copy of each; where the kept copy of the friction had
  // not been inlined, every derivative paid a call and its result through memory, and a
  // simulation took a third longer in one binary than in another (issue 16, bench_peers against
  // `billiard simulate`).
  template <typename T>
  EIGEN_ALWAYS_INLINE Eigen::Matrix<T, 5, 1> Accelerations(const Eigen::Matrix<T, 5, 1>& u) const {
    const ContactKinematics<T> k =
        ComputeContactKinematics(u[0], u[1], u[2], u[3], u[4], p_.contact, p_.ball.radius);
    return AccelerationsFrom(k, friction_(k));
  }

  // Inlined into the integrator's stages, which wait on it (see Accelerations).
  EIGEN_ALWAYS_INLINE BallState Derivative(const BallState& s) const {
    BallState ds;
    ds[kX] = s[kVx];
    ds[kY] = s[kVy];
    ds.tail<5>() = Accelerations<double>(s.tail<5>());
    return ds;
  }

  // The derivative and its Jacobian with respect to the state, in one pass.
  void DerivativeAndJacobian(const BallState& s, BallState* ds, StateJacobian* jac) const {
    if constexpr (HasAnalyticJacobian<Friction>::value) {
      AnalyticDerivativeAndJacobian(s, ds, jac);
    } else {
      DerivativeAndJacobianByAutoDiff(s, ds, jac);
    }
  }

  // The same by forward automatic differentiation through Accelerations, for any friction model.
  void DerivativeAndJacobianByAutoDiff(const BallState& s, BallState* ds,
                                       StateJacobian* jac) const {
    Eigen::Matrix<Jet, 5, 1> u;
    for (int i = 0; i < 5; ++i) u[i] = Jet(s[kVx + i], i);
    Assemble(s, Accelerations<Jet>(u), ds, jac);
  }

  const ModelParameters& parameters() const { return p_; }

 private:
  using Jet = ceres::Jet<double, 5>;

  // Eqs. 21-22 from the contact kinematics and the friction resultant: linear in the resultant
  // and in the rolling direction (dc, ds) of the rolling resistance.
  template <typename T>
  EIGEN_ALWAYS_INLINE Eigen::Matrix<T, 5, 1> AccelerationsFrom(
      const ContactKinematics<T>& k, const FrictionResultant<T>& f) const {
    const ContactParameters& c = p_.contact;
    const double g = p_.ball.gravity, r = p_.ball.radius, a = c.patch_radius, mu = c.mu;
    // The rolling resistance, eq. 15, is (mrx, mry) = 0.2 (ds, -dc). The constants are folded so
    // that each acceleration is at most two products and a sum of its inputs (see
    // ComputeContactKinematics).
    const double friction = mu * g;
    const double spin_by_friction = 2.5 * g * mu / r;
    const double spin_by_rolling = 2.5 * g * a / (r * r) * 0.2;
    Eigen::Matrix<T, 5, 1> du;
    du[0] = -friction * f.tsx;
    du[1] = -friction * f.tsy;
    du[2] = spin_by_rolling * k.ds - spin_by_friction * f.tsy;
    du[3] = spin_by_friction * f.tsx - spin_by_rolling * k.dc;
    du[4] = -2.5 * g / (r * r) * a * mu * f.ms;
    return du;
  }

  // The chain rule: d(resultant)/du = d(resultant)/d(kinematics) d(kinematics)/du, by hand; the
  // kinematics and the resultant then enter AccelerationsFrom as Jets carrying those gradients.
  void AnalyticDerivativeAndJacobian(const BallState& s, BallState* ds, StateJacobian* jac) const {
    const ContactParameters& c = p_.contact;
    const double r = p_.ball.radius;
    const ContactKinematics<double> k =
        ComputeContactKinematics(s[kVx], s[kVy], s[kWx], s[kWy], s[kWz], c, r);
    const Eigen::Matrix<double, 5, 5> dk = ContactKinematicsJacobian(s[kVx], s[kVy], c, r);
    FrictionJacobian df;
    const FrictionResultant<double> f = friction_.ResultantAndJacobian(k, &df);
    const Eigen::Matrix<double, 3, 5> df_du = df * dk;
    const auto jet = [](double value, const auto& gradient) {
      return Jet(value, gradient.transpose());
    };
    const ContactKinematics<Jet> kj{jet(k.vsx, dk.row(0)), jet(k.vsy, dk.row(1)),
                                    jet(k.ws, dk.row(2)), jet(k.dc, dk.row(3)),
                                    jet(k.ds, dk.row(4))};
    const FrictionResultant<Jet> fj{jet(f.tsx, df_du.row(0)), jet(f.tsy, df_du.row(1)),
                                    jet(f.ms, df_du.row(2))};
    Assemble(s, AccelerationsFrom(kj, fj), ds, jac);
  }

  // The 7-vector derivative and 7x7 Jacobian from the accelerations as Jets on (vx, ..., wz).
  static void Assemble(const BallState& s, const Eigen::Matrix<Jet, 5, 1>& du, BallState* ds,
                       StateJacobian* jac) {
    // Column by column: the 7x7 setZero() becomes a slow `rep stos` (8 % of the analytic call).
    jac->leftCols<2>().setZero();
    jac->topRightCorner<2, 5>().setZero();
    (*jac)(kX, kVx) = 1.0;
    (*jac)(kY, kVy) = 1.0;
    (*ds)[kX] = s[kVx];
    (*ds)[kY] = s[kVy];
    for (int i = 0; i < 5; ++i) {
      (*ds)[kVx + i] = du[i].a;
      jac->block<1, 5>(kVx + i, kVx) = du[i].v.transpose();
    }
  }

  ModelParameters p_;
  Friction friction_;
};

}  // namespace billiard::physics
