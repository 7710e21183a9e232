// One entry point for simulating a ball with any of the models.
//
//   approx       5-DOF model, approximate friction (eq. 17), RODAS4    (default, fast)
//   integral     5-DOF model, integral friction (eq. 16), RODAS4       (reference)
//   closed-form  sliding-then-rolling model of Jaroukh 2019, exact         (no integration)
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "sim/physics/ball_state.h"
#include "sim/physics/integral_friction.h"
#include "sim/physics/integrator.h"
#include "sim/physics/parameters.h"
#include "sim/physics/sensitivity.h"
#include "sim/physics/trajectory.h"

namespace billiard::physics {

enum class Model { kApproximate, kIntegral, kClosedForm };

std::string ModelName(Model m);
// "approx", "integral" or "closed-form"; std::nullopt for anything else.
std::optional<Model> ParseModel(const std::string& name);

// Integrators of the 5-DOF models: RODAS4 (L-stable Rosenbrock, the default) and DOPRI5 (the
// explicit baseline that shows what the stiffness costs).
enum class Integrator { kRodas4, kDopri5 };

std::string IntegratorName(Integrator i);
// "rodas4" or "dopri5"; std::nullopt for anything else.
std::optional<Integrator> ParseIntegrator(const std::string& name);

struct SimulationOptions {
  Model model = Model::kApproximate;
  Integrator integrator = Integrator::kRodas4;
  // Local error target of the integrator: metres for positions, m/s for velocities and
  // (rad/s) * r for spins. The default keeps 8 s endpoints within a fraction of a micrometre of
  // the converged ones (p95 0.3 um over the benchmark's 212 scenes, docs/benchmarks/report.md),
  // rest points included (within 0.6 um over 200 seeded shots: the rest stop is located on the
  // dense output, rest_test.cc); a tighter one buys nothing a table can show.
  double tolerance = 1e-6;
  // Target error of the integral model's quadrature on |T| and |Ms| (dimensionless).
  double quadrature_tolerance = 1e-6;
  // 5-DOF models: once the ball has stopped (ClassifyRest, rest.h), continue with the averaged
  // rest dynamics (BallAtRest) instead of resolving the regularization's creep and precession.
  // What this drops: the last v_rest^2 / (2 * 5/7 mu_r g) of travel (0.2 um with the paper's
  // parameters) and, for a ball that stops while pivoting, its circling about the reported centre
  // (radius |v|^2/|dv/dt|, tens of um). Off: integrate the regularized equations to t_end.
  bool rest_switch = true;
  // Attempted steps before the integrator gives up (std::runtime_error).
  long max_steps = IntegratorOptions().max_steps;
};

struct SimulationResult {
  BallState final_state = BallState::Zero();
  double rest_time = -1.0;  // when the rest switch took over; -1 if it did not
  IntegrationStats stats;   // zero for the closed form
  std::shared_ptr<const Trajectory> trajectory;
  std::optional<CalibratedQuadrature> quadrature;  // integral model only
};

// Simulates from `initial` at t = 0 to t_end >= 0. Throws std::invalid_argument on non-finite
// input, t_end < 0 or, for the 5-DOF models, parameters ValidateParameters refuses;
// std::runtime_error if the integrator fails.
SimulationResult Simulate(const ModelParameters& params, const BallState& initial, double t_end,
                          const SimulationOptions& options = {});

// Where a ball arrives: the first time its speed falls to a given value, or, for 0, where it comes
// to rest (for the 5-DOF models, where ClassifyRest calls it stopped, at the centre BallAtRest
// reports: the position Simulate ends at).
struct Arrival {
  bool reached = false;  // false: still faster than asked at t_max (state and time are there)
  double time = 0.0;
  BallState state = BallState::Zero();
  // d state / d initial state at the arrival, with the dependence of the arrival time on the
  // initial state included (5-DOF models with RODAS4, when asked; see sensitivity.h).
  std::optional<Sensitivity> sensitivity;
  IntegrationStats stats;
  std::shared_ptr<const Trajectory> trajectory;  // covers [0, time] at least
};

// Simulates from `initial` until it arrives at `speed` >= 0, or to t_max. Throws like Simulate,
// and std::invalid_argument when sensitivities are asked of the closed form or of DOPRI5.
Arrival SimulateArrival(const ModelParameters& params, const BallState& initial, double speed,
                        double t_max, const SimulationOptions& options = {},
                        bool with_sensitivity = false);

// Integrator settings for a 5-DOF simulation at the given tolerance (see SimulationOptions): the
// positions to `tolerance` [m], the velocities to the same number in m/s, capped at
// 10 min(eps_t, eps_r) a, the width of the friction law's linear zone, so that tiny
// regularizations do not make the slip chatter; wx, wy to that over r and wz to that over a (the
// same slip of the contact patch).
IntegratorOptions IntegratorOptionsFor(const ModelParameters& params, double tolerance);

}  // namespace billiard::physics
