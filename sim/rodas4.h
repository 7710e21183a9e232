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
// milliseconds while the ball rolls. Rosenbrock methods need no Newton iteration, only one LU of
// the 7x7 matrix I/(gamma h) - J per step, and J is exact (automatic differentiation).
#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "ball_state.h"
#include "dense_trajectory.h"

namespace billiard {

struct Rodas4Options {
  BallState abs_tol = BallState::Constant(1e-8);  // per component
  double rel_tol = 0.0;
  double initial_step = 1e-5;  // [s]
  long max_steps = 5'000'000;
};

struct IntegrationStats {
  long steps = 0;           // accepted steps
  long rejected_steps = 0;
  long rhs_evals = 0;       // right-hand-side evaluations, Jacobian passes included
  long jacobian_evals = 0;
};

// Where and why an integration ended.
struct Rodas4Result {
  BallState state;
  double t = 0.0;
  bool stopped = false;  // the stop predicate held before t_end
};

// Never ends an integration early.
struct NeverStop {
  bool operator()(const BallState&) const { return false; }
};

// Integrates x' = f(x) from x0 at t0 to t_end, or until stop(x) holds after an accepted step
// (or at t0). System provides
//   BallState Derivative(const BallState&) const and
//   void DerivativeAndJacobian(const BallState&, BallState*, StateJacobian*) const.
// Appends every accepted step to *dense when dense is non-null. Throws std::runtime_error when
// the step size underflows or max_steps is exceeded.
template <class System, class Stop = NeverStop>
Rodas4Result IntegrateRodas4(const System& system, const BallState& x0, double t0, double t_end,
                             const Rodas4Options& options, IntegrationStats* stats,
                             DenseTrajectory* dense = nullptr, const Stop& stop = Stop()) {
  using Matrix = Eigen::Matrix<double, 7, 7>;
  constexpr double gamma = 0.25;
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

  IntegrationStats local_stats;
  IntegrationStats& st = stats ? *stats : local_stats;
  BallState x = x0;
  double t = t0;
  if (stop(x)) return {x, t, true};
  if (t_end <= t0) return {x, t, false};
  double h = std::min(options.initial_step, t_end - t0);
  double previous_h = 0.0, previous_err = 1.0;  // of the last accepted step
  BallState f0, g1, g2, g3, g4, g5, g6, xs, x_new;
  Matrix jac;
  for (;;) {
    if (st.steps + st.rejected_steps >= options.max_steps) {
      throw std::runtime_error("RODAS4: more than " + std::to_string(options.max_steps) +
                               " steps before t = " + std::to_string(t_end));
    }
    const bool last = t + h >= t_end;
    if (last) h = t_end - t;

    system.DerivativeAndJacobian(x, &f0, &jac);
    ++st.jacobian_evals;
    ++st.rhs_evals;
    const Eigen::PartialPivLU<Matrix> lu(Matrix::Identity() / (gamma * h) - jac);
    const double inv_h = 1.0 / h;

    g1 = lu.solve(f0);
    xs = x + a21 * g1;
    g2 = lu.solve(system.Derivative(xs) + (c21 * inv_h) * g1);
    xs = x + a31 * g1 + a32 * g2;
    g3 = lu.solve(system.Derivative(xs) + inv_h * (c31 * g1 + c32 * g2));
    xs = x + a41 * g1 + a42 * g2 + a43 * g3;
    g4 = lu.solve(system.Derivative(xs) + inv_h * (c41 * g1 + c42 * g2 + c43 * g3));
    xs = x + a51 * g1 + a52 * g2 + a53 * g3 + a54 * g4;
    g5 = lu.solve(system.Derivative(xs) + inv_h * (c51 * g1 + c52 * g2 + c53 * g3 + c54 * g4));
    xs += g5;
    g6 = lu.solve(system.Derivative(xs) +
                  inv_h * (c61 * g1 + c62 * g2 + c63 * g3 + c64 * g4 + c65 * g5));
    x_new = xs + g6;
    st.rhs_evals += 5;

    // g6 is the difference between the fourth- and the embedded third-order solutions.
    double err = 0.0;
    for (int i = 0; i < 7; ++i) {
      const double scale =
          options.abs_tol[i] + options.rel_tol * std::max(std::abs(x[i]), std::abs(x_new[i]));
      err += (g6[i] / scale) * (g6[i] / scale);
    }
    err = std::sqrt(err / 7.0);

    if (!std::isfinite(err)) {
      ++st.rejected_steps;
      h *= 0.2;
    } else if (err <= 1.0) {
      if (dense) {
        dense->Append(t, last ? t_end : t + h, x, x_new,
                      d21 * g1 + d22 * g2 + d23 * g3 + d24 * g4 + d25 * g5,
                      d31 * g1 + d32 * g2 + d33 * g3 + d34 * g4 + d35 * g5);
      }
      ++st.steps;
      x = x_new;
      if (last) return {x, t_end, false};
      t += h;
      if (stop(x)) return {x, t, true};
      // Gustafsson's predictive controller (Hairer and Wanner's RODAS): the ratio of the last
      // two errors predicts the next one, which halves the rejections where the error changes
      // fast (entering and leaving the stiff phases).
      double factor = std::clamp(0.9 * std::pow(std::max(err, 1e-12), -0.25), 0.2, 6.0);
      if (previous_h > 0.0) {
        const double predicted = 0.9 * (h / previous_h) *
                                 std::pow(previous_err / (err * err), 0.25);
        factor = std::min(factor, std::clamp(predicted, 0.2, 6.0));
      }
      previous_h = h;
      previous_err = std::max(err, 1e-2);
      h *= factor;
    } else {
      ++st.rejected_steps;
      h *= std::clamp(0.9 * std::pow(err, -0.25), 0.2, 1.0);
    }
    if (h < 1e-14 * std::max(1.0, t)) {
      throw std::runtime_error("RODAS4: step size underflow at t = " + std::to_string(t));
    }
  }
}

}  // namespace billiard
