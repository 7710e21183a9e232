#include "planner/pot/pace.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "planner/pot/cue_elevation.h"
#include "planner/pot/lone_path.h"

namespace billiard::pot {

namespace {

// The aim for `shape` from the last one (a curve's path found again first, its bend changes
// with the shape).
bool Reaim(SearchContext& search, const Route& route, const Eigen::Vector2d& ghost, const StrokeShape& shape,
           double direction, Aimed* aimed) {
  const double from =
      route.kind == ShotKind::kCurve ? FirstHeading(search, route, shape, ghost) : aimed->heading;
  std::optional<Aimed> again = AimAt(search, shape, from, direction, false, aimed->slope);
  if (!again) return false;
  *aimed = *again;
  return true;
}

// K does not reach the pocket at `top`, the fastest stroke there is; where the hop sets it, the
// elevation that does (what a reader needs to tell the rail behind the cue ball from the pace).
Refusal NotReached(const SearchContext& search, double top, double elevation) {
  return Refusal{
      PotStatus::kNoStroke,
      "ball " + std::to_string(search.object_id()) + " does not reach " + search.pocket().name +
          " at " + MetresPerSecond(top) + ", the fastest stroke " +
          (top < search.params().cue.max_speed
               ? "whose hop the table's motion covers with the cue at " + Degrees(elevation)
               : std::string("of the cue"))};
}

}  // namespace

std::optional<Refusal> Pace(SearchContext& search, const Route& route, const Eigen::Vector2d& ghost,
                            StrokeShape* shape, Aimed* aimed, double direction) {
  const PotOptions& options = search.options();
  PaceFit& fit = search.pace_fit();
  // The cue's top speed, or the fastest whose hop the table's motion covers.
  const double top = TopCueSpeed(search, *shape, aimed->heading);
  // A curve is played at the top pace (PlanRoute starts it there): its bend grows with the pace
  // (the slide that bends it lasts in proportion), and within the hop limit it is small at best.
  if (route.kind == ShotKind::kCurve) {
    const Played played = search.Play(shape->At(aimed->heading), false, false);
    if (!played.arrival_speed) return NotReached(search, shape->speed, shape->elevation);
    fit.arrival = *played.arrival_speed;
    return std::nullopt;
  }
  double v_prev = 0.0, a2_prev = 0.0;
  bool have_prev = false;
  for (int i = 0; i < 8; ++i) {
    Played played = search.Play(shape->At(aimed->heading), false, false);
    const double a = played.arrival_speed.value_or(0.0);
    if (played.arrival_speed) fit.arrival = a;
    if (played.arrival_speed && std::abs(a - options.arrival_speed) < kArrivalTolerance) break;
    double next;
    if (!played.arrival_speed && !have_prev) {
      next = std::min(top, shape->speed * 1.6);
      if (shape->speed >= top) return NotReached(search, top, shape->elevation);
    } else if (!have_prev || !played.arrival_speed) {
      next = std::min(top, shape->speed * (played.arrival_speed ? 0.8 : 1.3));
    } else {
      const double v2 = shape->speed * shape->speed, a2 = a * a;
      const double slope = (a2 - a2_prev) / (v2 - v_prev * v_prev);
      if (slope > 0.0) fit.slope = slope;
      const double target = options.arrival_speed * options.arrival_speed;
      next = slope > 0.0 ? std::sqrt(std::max(kSlowestCue * kSlowestCue, v2 + (target - a2) / slope))
                         : shape->speed * 1.2;
      next = std::min(top, next);
    }
    if (played.arrival_speed) {
      v_prev = shape->speed;
      a2_prev = a * a;
      have_prev = true;
    }
    if (next == shape->speed) break;
    shape->speed = next;
    if (!Reaim(search, route, ghost, *shape, direction, aimed)) {
      return Refusal{PotStatus::kBlocked, "at " + std::to_string(next) +
                                              " m/s the cue ball no longer reaches ball " +
                                              std::to_string(search.object_id()) + " first"};
    }
  }
  return std::nullopt;
}

double SlowestPottingSpeed(const PaceFit& fit, double speed) {
  return fit.slope > 0.0 ? std::sqrt(std::max(0.0, speed * speed - fit.arrival * fit.arrival / fit.slope))
                         : 0.8 * speed;
}

}  // namespace billiard::pot
