#include "planner/shot_planner.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "planner/ceres_polish.h"
#include "planner/newton_aim.h"
#include "planner/plan_assembly.h"
#include "planner/reachability.h"
#include "planner/shot.h"

namespace billiard::planner {

std::string PlanStatusName(PlanStatus status) {
  switch (status) {
    case PlanStatus::kOk:
      return "ok";
    case PlanStatus::kInvalid:
      return "invalid";
    case PlanStatus::kOffTable:
      return "off_table";
    case PlanStatus::kUnreachable:
      return "unreachable";
    case PlanStatus::kNotConverged:
      return "not_converged";
    case PlanStatus::kCueBlocked:
      return "cue_blocked";
  }
  return "?";
}

physics::SimulationOptions PlannerOptions::DefaultRefinementSimulation() {
  physics::SimulationOptions o;
  o.model = physics::Model::kApproximate;
  o.integrator = physics::Integrator::kRodas4;
  // Endpoints within about 0.4 um of the converged model (docs/benchmarks/report.md), at two
  // thirds of the cost of the simulator's default.
  o.tolerance = 1e-6;
  return o;
}

namespace {

ShotPlan Refused(PlanStatus status, std::string reason) {
  ShotPlan plan;
  plan.status = status;
  plan.reason = std::move(reason);
  return plan;
}

// Step 1: a sound request and parameter set, start and target on the table, and a closed-form
// launch that reaches the target; the refusal otherwise.
std::optional<ShotPlan> CheckRequest(const ShotRequest& q, const physics::ModelParameters& params,
                                     LaunchSolution* guess) {
  try {
    physics::ValidateParameters(params);
  } catch (const std::invalid_argument& e) {
    return Refused(PlanStatus::kInvalid, std::string("invalid parameters: ") + e.what());
  }
  *guess = InvertClosedForm(q, physics::ClosedFormParameters::From(params));
  if (guess->malformed) return Refused(PlanStatus::kInvalid, guess->reason);
  if (!OnTable(q.from, params)) {
    return Refused(PlanStatus::kOffTable, "the ball is not on the playing surface");
  }
  if (!OnTable(q.to, params)) {
    return Refused(PlanStatus::kOffTable,
                   "the target is beyond the playing surface (its centre must stay a radius "
                   "inside the " +
                       std::to_string(params.table.length) + " x " +
                       std::to_string(params.table.width) + " m table)");
  }
  if (!guess->ok) return Refused(PlanStatus::kUnreachable, guess->reason);
  return std::nullopt;
}

// Step 3: the launch corrected until its simulated miss is below the tolerance, within the
// speed bounds (Aim, then Polish when Aim does not get there); returns the corrections made.
int Refine(Shot& shot, double launch[2]) {
  int iterations = 0;
  if (shot.options().jacobian == JacobianMethod::kSensitivities) {
    iterations = Aim(shot, launch);
    if (shot.Close(launch)) return iterations;
  }
  return iterations + Polish(shot, launch, shot.options().max_iterations - iterations);
}

ShotPlan Plan(const ShotRequest& q, const physics::ModelParameters& params,
              const PlannerOptions& options) {
  if (!(options.elevation >= 0.0 && options.elevation < M_PI / 2)) {
    return Refused(PlanStatus::kInvalid, "the cue's elevation must lie in [0, 90) deg");
  }
  LaunchSolution guess;
  if (auto refusal = CheckRequest(q, params, &guess)) return *refusal;
  const HeldSpin held = HoldTheSpin(q, guess, params);
  if (held.speeds.min > held.speeds.max) {
    return Refused(PlanStatus::kUnreachable, NoStrokeGivesTheSpin(held.spin_ratio, q, params));
  }
  Shot shot(q, held, params, options);

  ShotPlan plan;
  plan.slide_length = guess.slide_length;
  double p[2] = {held.speed, held.heading};
  // Not through the refinement's residual, which hides why a simulation failed: that reason (a
  // step budget, say) is what the refusal must report. With the sensitivities the refinement
  // needs at its first point, which this is.
  plan.closed_form_miss_m =
      (shot.Arrive(p[0], p[1], shot.NeedsSensitivities()).state.head<2>() - q.to).norm();
  if (auto reason = BeyondReach(shot, p[0], p[1])) {
    plan = Refused(PlanStatus::kUnreachable, *reason);
  } else {
    if (options.refine) plan.iterations = Refine(shot, p);
    const bool arrived = Predict(shot, p, &plan);
    Conclude(shot, p, arrived, &plan);
  }
  plan.simulations = shot.simulations();
  return plan;
}

}  // namespace

ShotPlan PlanShot(const ShotRequest& request, const physics::ModelParameters& params,
                  const PlannerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  ShotPlan plan;
  try {
    plan = Plan(request, params, options);
  } catch (const std::exception& e) {
    plan = Refused(PlanStatus::kNotConverged, std::string("simulation failed: ") + e.what());
  }
  plan.solve_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  return plan;
}

}  // namespace billiard::planner
