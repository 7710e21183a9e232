#include "simulator.h"

#include <cmath>
#include <stdexcept>

#include "ball_dynamics.h"
#include "closed_form.h"
#include "dopri5.h"
#include "rodas4.h"
#include "rest.h"

namespace billiard {

std::string ModelName(Model m) {
  switch (m) {
    case Model::kApproximate: return "approx";
    case Model::kIntegral: return "integral";
    case Model::kClosedForm: return "closed-form";
  }
  return "?";
}

std::optional<Model> ParseModel(const std::string& name) {
  for (Model m : {Model::kApproximate, Model::kIntegral, Model::kClosedForm}) {
    if (ModelName(m) == name) return m;
  }
  return std::nullopt;
}

std::string IntegratorName(Integrator i) {
  return i == Integrator::kDopri5 ? "dopri5" : "rodas4";
}

std::optional<Integrator> ParseIntegrator(const std::string& name) {
  for (Integrator i : {Integrator::kRodas4, Integrator::kDopri5}) {
    if (IntegratorName(i) == name) return i;
  }
  return std::nullopt;
}

IntegratorOptions IntegratorOptionsFor(const ModelParameters& params, double tolerance) {
  IntegratorOptions o;
  const double spin_tol = tolerance / params.ball.radius;
  o.abs_tol << tolerance, tolerance, tolerance, tolerance, spin_tol, spin_tol, spin_tol;
  return o;
}

namespace {

// Runs `system` with the chosen integrator.
template <class System, class Stop = NeverStop>
IntegrationResult Run(Integrator integrator, const System& system, const BallState& x0, double t0,
                      double t_end, const IntegratorOptions& options, IntegrationStats* stats,
                      DenseTrajectory* dense, const Stop& stop = Stop()) {
  if (integrator == Integrator::kDopri5) {
    return IntegrateWith<Dopri5Stepper>(system, x0, t0, t_end, options, stats, dense, stop);
  }
  return IntegrateWith<Rodas4Stepper>(system, x0, t0, t_end, options, stats, dense, stop);
}

template <class Friction>
SimulationResult Integrate(const ModelParameters& params, Friction friction,
                           const BallState& initial, double t_end, const SimulationOptions& options) {
  const BallDynamics<Friction> dynamics(params, std::move(friction));
  IntegratorOptions integrator = IntegratorOptionsFor(params, options.tolerance);
  integrator.max_steps = options.max_steps;
  auto dense = std::make_shared<DenseTrajectory>();
  SimulationResult result;
  IntegrationResult run;
  if (options.rest_switch) {
    run = Run(options.integrator, dynamics, initial, 0.0, t_end, integrator, &result.stats,
              dense.get(), [&dynamics](const BallState& s) {
                return ClassifyRest(s, dynamics) != RestKind::kMoving;
              });
  } else {
    run = Run(options.integrator, dynamics, initial, 0.0, t_end, integrator, &result.stats,
              dense.get());
  }
  if (run.stopped) {
    const BallAtRest<BallDynamics<Friction>> rest(dynamics, run.state,
                                                  ClassifyRest(run.state, dynamics));
    result.rest_time = run.t;
    run = Run(options.integrator, rest, rest.start(), run.t, t_end, integrator, &result.stats,
              dense.get());
  }
  result.final_state = run.state;
  if (dense->size() == 0) {  // t_end = 0: the trajectory is the initial state
    dense->Append(0.0, 0.0, initial, initial, BallState::Zero(), BallState::Zero());
  }
  result.trajectory = std::move(dense);
  return result;
}

}  // namespace

SimulationResult Simulate(const ModelParameters& params, const BallState& initial, double t_end,
                          const SimulationOptions& options) {
  if (!initial.allFinite()) throw std::invalid_argument("initial state has a non-finite number");
  if (!std::isfinite(t_end) || t_end < 0.0) {
    throw std::invalid_argument("end time must be a finite number >= 0");
  }
  if (options.model != Model::kClosedForm && !(options.tolerance > 0.0)) {
    throw std::invalid_argument("tolerance must be positive");
  }

  switch (options.model) {
    case Model::kApproximate:
      return Integrate(params, ApproximateFrictionModel{params.contact}, initial, t_end, options);
    case Model::kIntegral: {
      const CalibratedQuadrature q = CalibrateQuadrature(
          params.contact.eps_t, params.contact.d, options.quadrature_tolerance);
      SimulationResult r =
          Integrate(params, IntegralFrictionModel{IntegralFriction(q.order), params.contact.eps_t},
                    initial, t_end, options);
      r.quadrature = q;
      return r;
    }
    case Model::kClosedForm: {
      auto trajectory =
          std::make_shared<ClosedFormTrajectory>(ClosedFormParameters::From(params), initial);
      SimulationResult r;
      r.final_state = trajectory->At(t_end);
      r.trajectory = std::move(trajectory);
      return r;
    }
  }
  throw std::invalid_argument("unknown model");
}

}  // namespace billiard
