// When a 5-DOF ball has stopped, and what it does afterwards.
//
// The regularized equations have two ways of being at rest, and resolving either with the
// integrator costs thousands of steps for motion a real ball does not show:
//
//  - still: v and the contact slip are down at the regularization scale (eps_r a, eps_t a). The
//    ball creeps towards the invariant set v = 0, wx = wy = 0, where only wz evolves.
//  - balanced pivot: a ball that stops while spinning about the vertical settles where the slip
//    r |w_xy| exactly cancels the side force that the spin exerts on the pressure centre shifted by
//    d along v (eq. 17: vs = 3/32 pi bT d ws): the friction force vanishes, |v| stays near
//    eps_r a, and (v, wx, wy) precess together at about g a d / (2 r^2 |w_xy|) while shrinking in
//    proportion to wz. The centre traces a circle of radius |v|^2 / |dv/dt| (about 25 um with
//    the paper's parameters) and wz decays at the rate of that balanced contact, about 20 % slower
//    than a bare pivot's.
//
// BallAtRest replaces either by its average over the precession: the centre of that circle,
// v = wx = wy = 0, and wz driven by the moment of the contact at the stop scaled with wz (the
// moment does not depend on the precession phase, and the balanced slip is proportional to ws).
#pragma once

#include <ceres/jet.h>

#include <Eigen/Core>
#include <Eigen/LU>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/ball_state.h"

namespace billiard::physics {

enum class RestKind { kMoving, kStill, kBalancedPivot };

// A ball passing through v = 0 while its contact still pushes it (a draw reversing) is pushed by
// about mu m g; a balanced pivot by less than a thousandth of that.
inline constexpr double kBalancedForceFraction = 0.01;

// The speed below which a ball may be at rest: 10 eps_r a, ten times the width of the rolling
// resistance's regularization.
inline double RestSpeed(const ContactParameters& c) { return 10.0 * c.eps_r * c.patch_radius; }

// Classifies `s` with the thresholds RestSpeed (10 eps_r a) on |v|, 10 eps_t a on the slip and
// kBalancedForceFraction mu g on |dv/dt|.
template <class Dynamics>
RestKind ClassifyRest(const BallState& s, const Dynamics& dynamics) {
  const ModelParameters& p = dynamics.parameters();
  const ContactParameters& c = p.contact;
  const double v_rest = RestSpeed(c);
  if (s.segment<2>(kVx).squaredNorm() >= v_rest * v_rest) return RestKind::kMoving;
  const double u_rest = 10.0 * c.eps_t * c.patch_radius;
  const Eigen::Vector2d slip = ClothSlip(s, p.ball.radius);
  if (slip.squaredNorm() < u_rest * u_rest) return RestKind::kStill;
  const double a_rest = kBalancedForceFraction * c.mu * p.ball.gravity;
  const Eigen::Vector2d force = dynamics.Derivative(s).template segment<2>(kVx);
  if (s[kWz] != 0.0 && force.squaredNorm() < a_rest * a_rest) {
    return RestKind::kBalancedPivot;
  }
  return RestKind::kMoving;
}

template <class Dynamics>
class BallAtRest {
 public:
  // `stop` is a state that ClassifyRest put in `kind` (kStill or kBalancedPivot).
  BallAtRest(const Dynamics& full, const BallState& stop, RestKind kind)
      : full_(full), start_(stop), profile_(Eigen::Vector4d::Zero()) {
    start_.segment<4>(kVx).setZero();
    if (kind != RestKind::kBalancedPivot) return;
    profile_ = BalancedContact(stop).template segment<4>(kVx) / stop[kWz];
    // Centre of curvature of the path: X + |v|^2 a_n / |a_n|^2, a_n the normal acceleration.
    const Eigen::Vector2d v = stop.segment<2>(kVx);
    const Eigen::Vector2d a = full.Derivative(stop).template segment<2>(kVx);
    const Eigen::Vector2d a_n = a - a.dot(v) / v.squaredNorm() * v;
    if (a_n.squaredNorm() > 0.0) {
      start_.head<2>() += v.squaredNorm() / a_n.squaredNorm() * a_n;
    }
  }

  // Only wz moves (stage_matrix.h).
  static constexpr bool kTranslationInvariant = true;

  // The state the reduced dynamics starts from (see the file comment).
  const BallState& start() const { return start_; }

  BallState Derivative(const BallState& s) const {
    BallState ds = BallState::Zero();
    ds[kWz] = SpinAcceleration(s[kWz]);
    return ds;
  }

  void DerivativeAndJacobian(const BallState& s, BallState* ds, StateJacobian* jac) const {
    using Jet = ceres::Jet<double, 1>;
    const Jet dwz = SpinAcceleration(Jet(s[kWz], 0));
    ds->setZero();
    (*ds)[kWz] = dwz.a;
    jac->setZero();
    (*jac)(kWz, kWz) = dwz.v[0];
  }

 private:
  // The stop state with wx, wy moved (Newton on dv/dt = 0 at fixed v) to where the friction force
  // vanishes: the criterion catches the balance at 1 % of mu g, the precession settles near 0.1 %.
  BallState BalancedContact(BallState s) const {
    for (int iteration = 0; iteration < 4; ++iteration) {
      BallState f;
      StateJacobian jac;
      full_.DerivativeAndJacobian(s, &f, &jac);
      const Eigen::Matrix2d force_by_spin = jac.template block<2, 2>(kVx, kWx);
      s.segment<2>(kWx) -= force_by_spin.partialPivLu().solve(f.segment<2>(kVx));
    }
    return s;
  }

  template <typename T>
  T SpinAcceleration(const T& wz) const {
    Eigen::Matrix<T, 5, 1> u;
    for (int i = 0; i < 4; ++i) u[i] = profile_[i] * wz;
    u[4] = wz;
    return full_.template Accelerations<T>(u)[4];
  }

  const Dynamics& full_;
  BallState start_;
  Eigen::Vector4d profile_;  // (vx, vy, wx, wy) / wz of the balanced contact; zero when still
};

}  // namespace billiard::physics
