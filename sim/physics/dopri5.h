// DOPRI5: the explicit Dormand-Prince 5(4) Runge-Kutta pair (Hairer, Norsett and Wanner, Solving
// ODEs I, section II.5), with cubic Hermite dense output.
//
// The simulator's baseline, not its default: on the ball's stiff phases (slip near eps_t a, time
// constant about 4 us) its step is bounded by stability, not accuracy, so it measures what the
// stiffness costs (sim/README.md, docs/benchmarks/). It needs only Derivative() from the system.
#pragma once

#include "sim/physics/ball_state.h"
#include "sim/physics/integrator.h"

namespace billiard::physics {

template <class System>
class Dopri5Stepper {
 public:
  static constexpr const char* kName = "DOPRI5";
  static constexpr int kErrorOrder = 5;  // the embedded solution is of order 4

  explicit Dopri5Stepper(const System& system) : system_(system) {}

  void Attempt(const BallState& x, double h, StepAttempt* out, IntegrationStats* st) {
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                     a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                     a65 = -5103.0 / 18656;
    constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                     b6 = 11.0 / 84;
    // Fifth- minus fourth-order weights.
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                     e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;

    if (!has_f_) {
      f_ = system_.Derivative(x);
      ++st->rhs_evals;
      has_f_ = true;
    }
    const BallState& k1 = f_;
    const BallState k2 = system_.Derivative(x + h * a21 * k1);
    const BallState k3 = system_.Derivative(x + h * (a31 * k1 + a32 * k2));
    const BallState k4 = system_.Derivative(x + h * (a41 * k1 + a42 * k2 + a43 * k3));
    const BallState k5 = system_.Derivative(x + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
    const BallState k6 =
        system_.Derivative(x + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
    out->x_new = x + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    f_new_ = system_.Derivative(out->x_new);  // first stage of the next step (FSAL)
    st->rhs_evals += 6;
    out->error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * f_new_);
    // Cubic Hermite from the states and slopes at both ends, in DenseTrajectory's form.
    const BallState delta = out->x_new - x;
    out->c3 = h * k1 - delta;
    out->c4 = 2.0 * delta - h * (k1 + f_new_);
  }

  void Accept() { f_ = f_new_; }

 private:
  const System& system_;
  BallState f_, f_new_;  // slopes at the current state and at the last attempt's end
  bool has_f_ = false;
};

}  // namespace billiard::physics
