#include "sim/cue/stroke_limits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace billiard::cue {

namespace {

// The relative rounding of a hop computed at different headings (a few ulps of the strike).
constexpr double kHopRounding = 1e-9;

// The hop of a stroke per (m/s)^2 of its cue speed: the strike is linear in it.
double HopPerSpeedSquared(physics::CueStroke stroke, const Eigen::Vector2d& position,
                          const physics::ModelParameters& params) {
  stroke.speed = 1.0;
  return HopHeight(stroke, position, params);
}

std::string Fixed(double value, int digits) {
  std::ostringstream s;
  s.precision(digits);
  s << std::fixed << value;
  return s.str();
}

}  // namespace

double HopHeight(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                 const physics::ModelParameters& params) {
  const physics::BallState launch = physics::StrikeBall(stroke, position, params);
  return physics::Apex({0.0, physics::LaunchUpSpeed(stroke, launch)}, params.ball.gravity);
}

double TableMaxHop(const physics::ModelParameters& params) {
  return kMaxHopRadii * params.ball.radius;
}

double HopFreeSpeed(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                    const physics::ModelParameters& params, double max_hop) {
  const double per_speed_squared = HopPerSpeedSquared(stroke, position, params);
  if (per_speed_squared <= 0.0) return std::numeric_limits<double>::infinity();
  return std::sqrt(max_hop / per_speed_squared);
}

std::string HopReason(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                      const physics::ModelParameters& params, double max_hop) {
  const double hop = HopHeight(stroke, position, params);
  // A hop beyond the limit by the strike's rounding alone (the fastest stroke found at one heading,
  // played at another) is within it.
  if (hop <= max_hop * (1.0 + kHopRounding)) return "";
  return "the cue at " + Fixed(stroke.elevation * 180.0 / M_PI, 1) + " deg and " +
         Fixed(stroke.speed, 2) + " m/s would hop the ball " + Fixed(hop * 1e3, 2) +
         " mm, beyond the " + Fixed(max_hop * 1e3, 2) + " mm its motion covers (" +
         Fixed(HopFreeSpeed(stroke, position, params, max_hop), 2) + " m/s at most)";
}

std::variant<double, std::string> ElevationFor(const table::TableGeometry& table, double ball_radius,
                                               const std::vector<table::SceneBall>& balls, int cue_ball_id,
                                               const physics::CueStroke& stroke, const Robot& robot) {
  const ClearingElevation least = LeastClearingElevation(table, ball_radius, balls, cue_ball_id, stroke, robot);
  if (!least.elevation) return least.reason;
  // A cue that clears at the robot's lowest elevation has nothing to be raised over.
  if (*least.elevation <= robot.elevation.min) return std::max(*least.elevation, stroke.elevation);
  const double margined = std::min(*least.elevation + kElevationMargin, robot.elevation.max);
  return std::max(margined, stroke.elevation);
}

}  // namespace billiard::cue
