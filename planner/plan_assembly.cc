#include "planner/plan_assembly.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "planner/reachability.h"
#include "sim/physics/cue_strike.h"

namespace billiard::planner {

namespace {

std::string Millimetres(double metres) {
  std::ostringstream s;
  s.precision(3);
  s << metres * 1e3 << " mm";
  return s.str();
}

}  // namespace

bool Predict(Shot& shot, const double launch[2], ShotPlan* plan) {
  const PlannerOptions& options = shot.options();
  const physics::Arrival& arrival = shot.Arrive(launch[0], launch[1], false);
  const physics::BallState start = arrival.trajectory->At(0.0);
  plan->v0 = start.segment<2>(physics::kVx);
  plan->w0 = start.segment<3>(physics::kWx);
  plan->predicted_final = arrival.state.head<2>();
  plan->arrival_time = arrival.time;
  plan->refined_miss_m = (plan->predicted_final - shot.request().to).norm();
  const int samples =
      std::max(1, static_cast<int>(std::ceil(arrival.time / options.path_sample_dt)));
  plan->predicted_path.reserve(samples + 1);
  for (int i = 0; i <= samples; ++i) {
    const double t = arrival.time * i / samples;
    plan->predicted_path.push_back(i == samples
                                       ? plan->predicted_final
                                       : Eigen::Vector2d(arrival.trajectory->At(t).head<2>()));
  }
  return arrival.reached;
}

void Conclude(Shot& shot, const double launch[2], bool arrived, ShotPlan* plan) {
  const PlannerOptions& options = shot.options();
  if (!arrived || (options.refine && plan->refined_miss_m > options.acceptable_miss)) {
    if (auto reason = BeyondReach(shot, launch[0], launch[1])) {
      plan->status = PlanStatus::kUnreachable;
      plan->reason = *reason;
    } else {
      plan->status = PlanStatus::kNotConverged;
      plan->reason = "refinement ended " + Millimetres(plan->refined_miss_m) + " from the target";
    }
    return;
  }
  for (const Eigen::Vector2d& x : plan->predicted_path) {
    if (!OnTable(x, shot.params())) {
      plan->status = PlanStatus::kUnreachable;
      plan->reason = "the path leaves the playing surface (a cushion is in the way)";
      return;
    }
  }
  const physics::StrokeSolution stroke = physics::StrokeFor(plan->v0, plan->w0, shot.params(), std::tan(options.elevation));
  if (!stroke.ok) {
    plan->status = PlanStatus::kUnreachable;
    plan->reason = stroke.reason;
    return;
  }
  plan->stroke = stroke.stroke;
  plan->status = PlanStatus::kOk;
}

}  // namespace billiard::planner
