// RODAS4: a stiffly accurate, L-stable Rosenbrock method of order 4 (embedded order 3) with a
// third-order dense output (Hairer and Wanner, Solving ODEs II, section IV.7; coefficients of
// their code RODAS, also used by Boost.Odeint's rosenbrock4).
//
// Why this method for the ball: the regularized friction makes the equations stiff whenever the
// slip falls to eps_t a (end of sliding, a time constant of about 4 us) and again when the ball
// comes to rest, while the spinning and sliding phases in between are smooth and non-stiff.
// An explicit method is limited by stability to steps of a few microseconds for the whole rolling
// phase (about 540,000 steps for Fig. 6); an L-stable linearly implicit method damps the stiff
// slip mode at any step size, so its step is set by accuracy alone and grows to tens of
// milliseconds while the ball rolls. Rosenbrock methods need no Newton iteration, only one inverse
// of the 7x7 matrix I/(gamma h) - J per step (of its 5x5 block for the ball: stage_matrix.h), and
// J is exact (hand-derived for the approximate model, automatic differentiation for the integral
// one: ball_dynamics.h).
#pragma once

#include <Eigen/Core>

#include "sim/physics/ball_state.h"
#include "sim/physics/dense_trajectory.h"
#include "sim/physics/integrator.h"
#include "sim/physics/stage_matrix.h"

namespace billiard::physics {

// One RODAS4 step at a time, for IntegrateAdaptive. System provides
//   BallState Derivative(const BallState&) const and
//   void DerivativeAndJacobian(const BallState&, BallState*, StateJacobian*) const,
// and may declare kTranslationInvariant (stage_matrix.h).
template <class System>
class Rodas4Stepper {
 public:
  static constexpr const char* kName = "RODAS4";
  static constexpr int kErrorOrder = 4;  // the embedded solution is of order 3
  // The stage matrix is I/(kGamma h) - J.
  static constexpr double kGamma = 0.25;

  explicit Rodas4Stepper(const System& system) : system_(system) {}

  void Attempt(const BallState& x, double h, StepAttempt* out, IntegrationStats* st) {
    // The stage times (0.386, 0.21, 0.63, 1) do not enter: the ball's equations are autonomous.
    constexpr double a21 = 1.544;
    constexpr double a31 = 0.9466785280815826, a32 = 0.2557011698983284;
    constexpr double a41 = 3.314825187068521, a42 = 2.896124015972201, a43 = 0.9986419139977817;
    constexpr double a51 = 1.221224509226641, a52 = 6.019134481288629, a53 = 12.53708332932087,
                     a54 = -0.6878860361058950;
    constexpr double c21 = -5.6688;
    constexpr double c31 = -2.430093356833875, c32 = -0.2063599157091915;
    constexpr double c41 = -0.1073529058151375, c42 = -9.594562251023355, c43 = -20.47028614809616;
    constexpr double c51 = 7.496443313967647, c52 = -10.24680431464352, c53 = -33.99990352819905,
                     c54 = 11.70890893206160;
    constexpr double c61 = 8.083246795921522, c62 = -7.981132988064893, c63 = -31.52159432874371,
                     c64 = 16.31930543123136, c65 = -6.058818238834054;
    constexpr double d21 = 10.12623508344586, d22 = -7.487995877610167, d23 = -34.80091861555747,
                     d24 = -7.992771707568823, d25 = 1.025137723295662;
    constexpr double d31 = -0.6762803392801253, d32 = 6.087714651680015, d33 = 16.43084320892478,
                     d34 = 24.76722511418386, d35 = -6.594389125716872;

    // A rejected step is retried from the same state with a smaller h: f0 and J stay valid.
    if (!has_jacobian_) {
      system_.DerivativeAndJacobian(x, &f0_, &jac_);
      ++st->jacobian_evals;
      ++st->rhs_evals;
      has_jacobian_ = true;
    }
    st->rhs_evals += 5;
    StageMatrix<IsTranslationInvariant<System>::value> m;
    m.Invert(jac_, 1.0 / (kGamma * h));
    const BallState& f0 = f0_;
    const double inv_h = 1.0 / h;

    const BallState g1 = m.Solve(f0);
    BallState xs = x + a21 * g1;
    const BallState g2 = m.Solve(system_.Derivative(xs) + (c21 * inv_h) * g1);
    xs = x + a31 * g1 + a32 * g2;
    const BallState g3 = m.Solve(system_.Derivative(xs) + inv_h * (c31 * g1 + c32 * g2));
    xs = x + a41 * g1 + a42 * g2 + a43 * g3;
    const BallState g4 = m.Solve(system_.Derivative(xs) + inv_h * (c41 * g1 + c42 * g2 + c43 * g3));
    xs = x + a51 * g1 + a52 * g2 + a53 * g3 + a54 * g4;
    const BallState g5 =
        m.Solve(system_.Derivative(xs) + inv_h * (c51 * g1 + c52 * g2 + c53 * g3 + c54 * g4));
    xs += g5;
    // g6 is the difference between the fourth- and the embedded third-order solutions.
    out->error = m.Solve(system_.Derivative(xs) +
                         inv_h * (c61 * g1 + c62 * g2 + c63 * g3 + c64 * g4 + c65 * g5));
    out->x_new = xs + out->error;
    out->c3 = d21 * g1 + d22 * g2 + d23 * g3 + d24 * g4 + d25 * g5;
    out->c4 = d31 * g1 + d32 * g2 + d33 * g3 + d34 * g4 + d35 * g5;
  }

  void Accept() { has_jacobian_ = false; }

 private:
  const System& system_;
  // f and J at the state of the last attempt, until a step from it is accepted.
  BallState f0_;
  Eigen::Matrix<double, 7, 7> jac_;
  bool has_jacobian_ = false;
};

}  // namespace billiard::physics
