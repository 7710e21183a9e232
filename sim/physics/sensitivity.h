// Forward sensitivities of a 5-DOF integration: S(t) = d x(t) / d x(0), carried along with the
// state step by step.
//
// Why forward sensitivities: the planner refines a shot by Gauss-Newton on where the simulated
// ball ends, and needs the derivative of that end point with respect to the launch. Finite
// differences would cost one simulation per unknown and, through the stiff end of sliding, lose
// half their digits; the variational equation S' = J(x(t)) S costs two Jacobians and one small
// linear solve per step on top of the simulation.
//
// How (staggered direct method): RODAS4 takes each step of the state as usual, with its error
// control; once the step is accepted, S is advanced over the same step by the two-stage Radau IIA
// collocation method (order 3, L-stable, Hairer and Wanner II, section IV.5) applied to the linear
// equation S' = J(x(t)) S, with x(t) from the step's dense output. The variational equation is as
// stiff as the ball (slip modes of 2e5 1/s), so it needs an L-stable method; being linear, it
// needs no Newton iteration, only one 14x14 solve. Carrying S inside the Rosenbrock stages instead
// would need d(J S)/dx in the stage matrix; without it, S was off by tens of per cent on
// spin-heavy shots (measured against central differences).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>

#include "sim/physics/dense_trajectory.h"
#include "sim/physics/integrator.h"
#include "sim/physics/rodas4.h"

namespace billiard::physics {

using Sensitivity = Eigen::Matrix<double, 7, 7>;

// A RODAS4 stepper for IntegrateAdaptive that also advances S over every accepted step.
template <class System>
class Rodas4SensitivityStepper {
 public:
  static constexpr const char* kName = Rodas4Stepper<System>::kName;
  static constexpr int kErrorOrder = Rodas4Stepper<System>::kErrorOrder;

  explicit Rodas4SensitivityStepper(const System& system) : system_(system), state_(system) {}

  void Attempt(const BallState& x, double h, StepAttempt* out, IntegrationStats* st) {
    state_.Attempt(x, h, out, st);
    x0_ = x;
    h_ = h;
    attempt_ = *out;
  }

  void Accept() {
    state_.Accept();
    previous_ = s_;
    s_ = Advance(previous_, 1.0);
  }

  // S at the last accepted step.
  const Sensitivity& sensitivity() const { return s_; }
  // S at a fraction theta in [0, 1] of the last accepted step (where an event was found).
  Sensitivity SensitivityWithinLastStep(double theta) const { return Advance(previous_, theta); }

 private:
  // One Radau IIA step from s at the start of the last attempt over theta h: with c = (1/3, 1),
  // K_i = A_i (s + H sum_j a_ij K_j), s_new = s + H (3/4 K1 + 1/4 K2), H = theta h.
  Sensitivity Advance(const Sensitivity& s, double theta) const {
    constexpr double a11 = 5.0 / 12, a12 = -1.0 / 12, a21 = 3.0 / 4, a22 = 1.0 / 4;
    using Matrix14 = Eigen::Matrix<double, 14, 14>;
    const double h = theta * h_;
    const Sensitivity a1 = Jacobian(
        DenseTrajectory::Interpolate(x0_, attempt_.x_new, attempt_.c3, attempt_.c4, theta / 3.0));
    const Sensitivity a2 = Jacobian(
        DenseTrajectory::Interpolate(x0_, attempt_.x_new, attempt_.c3, attempt_.c4, theta));
    Matrix14 m = Matrix14::Identity();
    m.topLeftCorner<7, 7>() -= h * a11 * a1;
    m.topRightCorner<7, 7>() = -h * a12 * a1;
    m.bottomLeftCorner<7, 7>() = -h * a21 * a2;
    m.bottomRightCorner<7, 7>() -= h * a22 * a2;
    Eigen::Matrix<double, 14, 7> rhs;
    rhs << a1 * s, a2 * s;
    const Eigen::Matrix<double, 14, 7> k = m.partialPivLu().solve(rhs);
    return s + h * (a21 * k.topRows<7>() + a22 * k.bottomRows<7>());  // stiffly accurate
  }

  Sensitivity Jacobian(const BallState& x) const {
    BallState f;
    Sensitivity jac;
    system_.DerivativeAndJacobian(x, &f, &jac);
    return jac;
  }

  const System& system_;
  Rodas4Stepper<System> state_;
  BallState x0_ = BallState::Zero();
  double h_ = 0.0;
  StepAttempt attempt_;
  Sensitivity s_ = Sensitivity::Identity(), previous_ = Sensitivity::Identity();
};

}  // namespace billiard::physics
