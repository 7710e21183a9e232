// What the ODE integrators of the simulator share: options, statistics, and the adaptive driver
// that runs an embedded pair (RODAS4 in rodas4.h, DOPRI5 in dopri5.h) with error control, dense
// output and a stop predicate.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/physics/ball_state.h"
#include "sim/physics/dense_trajectory.h"

namespace billiard::physics {

struct IntegratorOptions {
  BallState abs_tol = BallState::Constant(1e-8);  // per component
  double rel_tol = 0.0;
  double initial_step = 1e-5;  // [s]
  long max_steps = 5'000'000;
};

struct IntegrationStats {
  long steps = 0;  // accepted steps
  long rejected_steps = 0;
  long rhs_evals = 0;  // right-hand-side evaluations, Jacobian passes included
  long jacobian_evals = 0;
};

// Where and why an integration ended.
struct IntegrationResult {
  BallState state;
  double t = 0.0;
  bool stopped = false;  // the stop predicate held before t_end
};

// Never ends an integration early.
struct NeverStop {
  bool operator()(const BallState&) const { return false; }
};

// One attempted step of an embedded pair: the new state, the difference between the two
// solutions, and the coefficients of the dense output over the step (DenseTrajectory::Append).
struct StepAttempt {
  BallState x_new, error, c3, c4;
};

namespace internal {

// x^(-1/order), the step-size factor of an error ratio: for RODAS4's order 4 by two square roots,
// a tenth of pow()'s cost, which was paid twice per step.
template <int kOrder>
double InverseRoot(double x) {
  if constexpr (kOrder == 4) {
    return 1.0 / std::sqrt(std::sqrt(x));
  } else {
    return std::pow(x, -1.0 / kOrder);
  }
}

}  // namespace internal

// Integrates x' = f(x) from x0 at t0 to t_end, or until stop(x) holds after an accepted step
// (or at t0), with steps attempted by `stepper`:
//   static constexpr const char* kName; static constexpr int kErrorOrder;  (error ~ h^order)
//   void Attempt(const BallState& x, double h, StepAttempt* out, IntegrationStats* stats);
//   void Accept();  (the last attempt became the current state)
// Appends every accepted step to *dense when dense is non-null. Throws std::runtime_error when
// the step size underflows or max_steps is exceeded.
template <class Stepper, class Stop = NeverStop>
IntegrationResult IntegrateAdaptive(Stepper& stepper, const BallState& x0, double t0, double t_end,
                                    const IntegratorOptions& options, IntegrationStats* stats,
                                    DenseTrajectory* dense = nullptr, const Stop& stop = Stop()) {
  constexpr int kOrder = Stepper::kErrorOrder;
  IntegrationStats local_stats;
  IntegrationStats& st = stats ? *stats : local_stats;
  BallState x = x0;
  double t = t0;
  if (stop(x)) return {x, t, true};
  if (t_end <= t0) return {x, t, false};
  double h = std::min(options.initial_step, t_end - t0);
  double previous_h = 0.0, previous_err = 1.0;  // of the last accepted step
  bool after_rejection = false;
  StepAttempt step;
  for (;;) {
    if (st.steps + st.rejected_steps >= options.max_steps) {
      throw std::runtime_error(std::string(Stepper::kName) + ": more than " +
                               std::to_string(options.max_steps) +
                               " steps before t = " + std::to_string(t_end));
    }
    const bool last = t + h >= t_end;
    if (last) h = t_end - t;
    stepper.Attempt(x, h, &step, &st);

    double err = 0.0;  // RMS of the error over the per-component tolerances
    for (int i = 0; i < 7; ++i) {
      const double scale =
          options.abs_tol[i] + options.rel_tol * std::max(std::abs(x[i]), std::abs(step.x_new[i]));
      err += (step.error[i] / scale) * (step.error[i] / scale);
    }
    err = std::sqrt(err / 7.0);

    if (!std::isfinite(err)) {
      ++st.rejected_steps;
      after_rejection = true;
      h *= 0.2;
    } else if (err <= 1.0) {
      if (dense) dense->Append(t, last ? t_end : t + h, x, step.x_new, step.c3, step.c4);
      ++st.steps;
      stepper.Accept();
      x = step.x_new;
      t = last ? t_end : t + h;
      // The last step too: an event inside the step that reaches t_end (a rolling ball's steps
      // grow to seconds) ends the integration there as anywhere else.
      if (stop(x)) return {x, t, true};
      if (last) return {x, t, false};
      // Gustafsson's predictive controller (as in Hairer and Wanner's RODAS): the ratio of the
      // last two errors predicts the next one, which cuts the rejections where the error changes
      // fast (entering and leaving the stiff phases).
      double factor =
          std::clamp(0.9 * internal::InverseRoot<kOrder>(std::max(err, 1e-12)), 0.2, 6.0);
      if (previous_h > 0.0) {
        const double predicted =
            0.9 * (h / previous_h) * internal::InverseRoot<kOrder>(err * err / previous_err);
        factor = std::min(factor, std::clamp(predicted, 0.2, 6.0));
      }
      // Right after a rejection the step does not grow (as in RODAS): the error just failed
      // at a larger step.
      if (after_rejection) factor = std::min(factor, 1.0);
      after_rejection = false;
      previous_h = h;
      previous_err = std::max(err, 1e-2);
      h *= factor;
    } else {
      ++st.rejected_steps;
      after_rejection = true;
      h *= std::clamp(0.9 * internal::InverseRoot<kOrder>(err), 0.2, 1.0);
    }
    if (h < 1e-14 * std::max(1.0, t)) {
      throw std::runtime_error(std::string(Stepper::kName) +
                               ": step size underflow at t = " + std::to_string(t));
    }
  }
}

// IntegrateAdaptive with a fresh StepperT<System>, e.g. IntegrateWith<Rodas4Stepper>(system, ...).
template <template <class> class StepperT, class System, class Stop = NeverStop>
IntegrationResult IntegrateWith(const System& system, const BallState& x0, double t0, double t_end,
                                const IntegratorOptions& options, IntegrationStats* stats,
                                DenseTrajectory* dense = nullptr, const Stop& stop = Stop()) {
  StepperT<System> stepper(system);
  return IntegrateAdaptive(stepper, x0, t0, t_end, options, stats, dense, stop);
}

}  // namespace billiard::physics
