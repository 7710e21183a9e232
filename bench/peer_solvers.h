// The off-the-shelf stiff solvers our RODAS4 is measured against, run on our equations.
//
// Both integrate the approximate 5-DOF model, BallDynamics<ApproximateFrictionModel>
// (sim/physics/ball_dynamics.h), with its hand-derived Jacobian, from t = 0 to t_end, and stop
// there: they have no rest switch, so a ball that stops while pivoting (Figs. 9, 10) is integrated
// through the regularization's precession to the end, as the regularized equations say. Their
// error weights are ours (physics::IntegratorOptionsFor: a tolerance in metres for positions, m/s
// for velocities, (rad/s) r for spins, each capped like ours), so that one tolerance means the
// same thing to all three.
//
//   Boost.Odeint rosenbrock4 (Ahnert & Mulansky 2011): the same method family as ours, with the
//     coefficients of Hairer & Wanner's RODAS (1996), under Odeint's own step controller
//     (rosenbrock4_controller).
//   SUNDIALS CVODE (Hindmarsh et al. 2005): variable-order BDF (orders 1-5) with Newton
//     iteration, the dense direct linear solver, and our Jacobian.
#pragma once

#include <memory>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

// Where a peer ended and what it took.
struct PeerRun {
  physics::BallState final_state = physics::BallState::Zero();
  long steps = 0;           // accepted
  long rejected_steps = 0;  // error test failures (and, for CVODE, Newton convergence failures)
  long rhs_evals = 0;       // right-hand sides, the ones inside Jacobian passes included
  long jacobian_evals = 0;
};

// Runs the approximate model to t_end with Odeint's rosenbrock4 at `tolerance` (the meaning of
// SimulationOptions::tolerance). Throws std::runtime_error after `max_steps` attempted steps.
PeerRun OdeintRosenbrock4(const physics::ModelParameters& p, const physics::BallState& initial,
                          double t_end, double tolerance, long max_steps = 5'000'000);

// CVODE's BDF on the approximate model at one tolerance. The solver's memory is made once and
// re-initialised for every run (CVodeReInit), as a caller running many shots would: the peer at
// its best, its set-up not charged to the shot. Not copyable; one per thread.
class CvodeBdf {
 public:
  CvodeBdf(const physics::ModelParameters& p, double tolerance, long max_steps = 5'000'000);
  ~CvodeBdf();
  CvodeBdf(const CvodeBdf&) = delete;
  CvodeBdf& operator=(const CvodeBdf&) = delete;

  // Runs from `initial` at t = 0 to t_end (exactly: CVODE's stop time). Throws
  // std::runtime_error when CVODE fails (its message and flag).
  PeerRun Run(const physics::BallState& initial, double t_end);

 private:
  struct Solver;
  std::unique_ptr<Solver> solver_;
};

}  // namespace billiard::bench
