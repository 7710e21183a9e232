#include "planner/newton_aim.h"

#include <algorithm>
#include <cmath>
#include <exception>

namespace billiard::planner {

namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

Reach ReachOf(const physics::Arrival& arrival, const Eigen::Vector2d& from, double heading) {
  const Eigen::Vector2d x = arrival.state.head<2>() - from;
  return {x.norm(), std::remainder(std::atan2(x.y(), x.x()) - heading, 2.0 * M_PI)};
}

double QuadraticRoot(double f, double b, double c) {
  const double discriminant = b * b - 4.0 * c * f;
  return discriminant < 0.0 ? -f / b : -2.0 * f / (b + std::sqrt(discriminant));
}

int Aim(Shot& shot, double launch[2]) {
  const ShotRequest& q = shot.request();
  const physics::LaunchSpeedRange& speeds = shot.speeds();
  const Eigen::Vector2d want = q.to - q.from;
  const double distance = want.norm(), bearing = std::atan2(want.y(), want.x());
  const double s0 = launch[0];
  const physics::Arrival& first = shot.Arrive(s0, launch[1], true);
  if (shot.Close(launch)) return 0;
  const Reach r0 = ReachOf(first, q.from, launch[1]);
  // The rates of change of the reach and the turn with e = s^2, from d x / d s.
  const Eigen::Vector2d x = first.state.head<2>() - q.from;
  const Eigen::Vector2d dx_de =
      first.sensitivity->topRows<2>() * shot.launch().Derivative(s0, launch[1]).col(0) / (2.0 * s0);
  const Reach rate{x.dot(dx_de) / r0.reach, Cross(x, dx_de) / x.squaredNorm()};
  if (!(rate.reach > 0.0) || !std::isfinite(rate.turn)) return 0;
  Reach curvature;
  int steps = 0;
  while (steps < std::min(kAimSteps, shot.options().max_iterations)) {
    const double de = QuadraticRoot(r0.reach - distance, rate.reach, curvature.reach);
    const double speed = std::sqrt(s0 * s0 + de);
    if (!(speed >= speeds.min && speed <= speeds.max)) break;
    const double heading = bearing - (r0.turn + (rate.turn + curvature.turn * de) * de);
    Reach r;
    try {
      r = ReachOf(shot.Arrive(speed, heading, false), q.from, heading);
    } catch (const std::exception&) {
      break;  // Polish shrinks its step where a simulation fails
    }
    launch[0] = speed;
    launch[1] = heading;
    ++steps;
    if (shot.Close(launch) || de == 0.0) break;
    curvature = {(r.reach - r0.reach - rate.reach * de) / (de * de),
                 (r.turn - r0.turn - rate.turn * de) / (de * de)};
  }
  return steps;
}

}  // namespace billiard::planner
