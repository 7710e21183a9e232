#include "planner/pot/cue_elevation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace billiard::pot {

namespace {

constexpr int kCueBall = 0;

// A length in millimetres, in words: "3.2 mm".
std::string Millimetres(double metres) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed << metres * 1e3 << " mm";
  return s.str();
}

}  // namespace

double HopHeight(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                 const physics::ModelParameters& params) {
  const physics::BallState launch = physics::StrikeBall(stroke, position, params);
  const Eigen::Vector2d along(std::cos(stroke.heading), std::sin(stroke.heading));
  // The impulse along the cue's axis drives the ball down by its horizontal part times
  // tan(elevation); the sideways part (squirt) is horizontal.
  const double down = std::max(0.0, launch.segment<2>(physics::kVx).dot(along)) * std::tan(stroke.elevation);
  const double up = kBedRestitution * down;
  return up * up / (2.0 * params.ball.gravity);
}

std::variant<double, std::string> ElevationFor(const table::TableGeometry& table, double ball_radius,
                                               const std::vector<table::SceneBall>& balls,
                                               const physics::CueStroke& stroke, const cue::Robot& robot) {
  const cue::ClearingElevation least = cue::LeastClearingElevation(table, ball_radius, balls, kCueBall, stroke, robot);
  if (!least.elevation) return least.reason;
  // A cue that clears at the robot's lowest elevation has nothing to be raised over.
  if (*least.elevation <= robot.elevation.min) return std::max(*least.elevation, stroke.elevation);
  const double margined = std::min(*least.elevation + kElevationMargin, robot.elevation.max);
  return std::max(margined, stroke.elevation);
}

std::variant<double, Refusal> NeededElevation(const SearchContext& search, const StrokeShape& shape,
                                              double heading) {
  const std::optional<cue::Robot>& robot = search.options().robot;
  if (!robot) return shape.elevation;
  std::variant<double, std::string> e = ElevationFor(search.table(), search.radius(), search.balls(), shape.At(heading), *robot);
  if (const std::string* why = std::get_if<std::string>(&e)) return Refusal{PotStatus::kCueBlocked, *why};
  return std::get<double>(e);
}

std::optional<Refusal> CheckCue(const SearchContext& search, const physics::CueStroke& stroke,
                                std::optional<cue::CueClearance>* clearance) {
  if (const std::optional<cue::Robot>& robot = search.options().robot) {
    *clearance = cue::Clearance(search.table(), search.radius(), search.balls(), kCueBall, stroke, *robot);
    if (!(*clearance)->clears) {
      Refusal blocked{PotStatus::kCueBlocked, "at " + Degrees(stroke.elevation) + " " + (*clearance)->what +
                                                  " is " + Millimetres(-(*clearance)->distance) +
                                                  " into the cue"};
      const std::variant<double, Refusal> needed =
          NeededElevation(search, StrokeShape{stroke.speed, stroke.tip_side, stroke.tip_height, 0.0}, stroke.heading);
      if (const double* e = std::get_if<double>(&needed)) blocked.elevation_needed = *e;
      return blocked;
    }
  }
  const double hop = HopHeight(stroke, search.cue_position(), search.params());
  if (hop > kMaxHop) {
    return Refusal{PotStatus::kNoStroke, "the cue at " + Degrees(stroke.elevation) + " would lift the ball off the cloth (a hop of " +
                                             Millimetres(hop) + ", beyond the " + Millimetres(kMaxHop) +
                                             " the strike model's ball on the cloth covers)"};
  }
  return std::nullopt;
}

}  // namespace billiard::pot
