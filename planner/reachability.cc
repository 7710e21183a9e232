#include "planner/reachability.h"

#include <sstream>

namespace billiard::planner {

bool OnTable(const Eigen::Vector2d& x, const physics::ModelParameters& p) {
  const double r = p.ball.radius;
  return x.x() >= r && x.x() <= p.table.length - r && x.y() >= r && x.y() <= p.table.width - r;
}

std::string NoStrokeGivesTheSpin(double spin_ratio, const ShotRequest& q,
                                 const physics::ModelParameters& params) {
  std::ostringstream reason;
  reason.precision(3);
  reason << "no stroke gives this spin (R w / v = " << spin_ratio
         << " across the line, wz = " << q.side_spin << " rad/s) within the robot's tip offset of "
         << params.cue.max_tip_offset << " r and cue speed of " << params.cue.max_speed << " m/s";
  return reason.str();
}

std::optional<std::string> BeyondReach(Shot& shot, double speed, double heading) {
  const ShotRequest& q = shot.request();
  const physics::LaunchSpeedRange& speeds = shot.speeds();
  const PlannerOptions& options = shot.options();
  const bool slowest = speed <= speeds.min, fastest = speed >= speeds.max;
  if (!slowest && !fastest) return std::nullopt;
  const double bound = slowest ? speeds.min : speeds.max;
  const double distance = (q.to - q.from).norm();
  const double travel = (shot.Arrive(bound, heading, false).state.head<2>() - q.from).norm();
  std::ostringstream reason;
  reason.precision(3);
  if (slowest && travel > distance + options.acceptable_miss) {
    reason << "the side spin needs a launch of at least " << bound << " m/s to stay within "
           << "the tip offset of " << shot.params().cue.max_tip_offset << " r, which carries the "
           << "ball " << travel << " m, past the target";
    return reason.str();
  }
  if (fastest && travel < distance - options.acceptable_miss) {
    reason << "needs a faster launch than the robot's cue speed of " << shot.params().cue.max_speed
           << " m/s gives (at most " << bound << " m/s, which reaches " << travel << " m)";
    return reason.str();
  }
  return std::nullopt;
}

}  // namespace billiard::planner
