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

double TopCueSpeed(const SearchContext& search, const StrokeShape& shape, double heading) {
  double top = std::min(search.params().cue.max_speed,
                        cue::HopFreeSpeed(shape.At(heading), search.cue_position(), search.params(),
                                          cue::TableMaxHop(search.params())));
  if (const std::optional<cue::Robot>& robot = search.options().robot) top = std::min(top, robot->speed.max);
  return top;
}

std::variant<double, Refusal> NeededElevation(const SearchContext& search, const StrokeShape& shape,
                                              double heading) {
  const std::optional<cue::Robot>& robot = search.options().robot;
  if (!robot) return shape.elevation;
  std::variant<double, std::string> e =
      cue::ElevationFor(search.table(), search.radius(), search.balls(), kCueBall, shape.At(heading), *robot);
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
  const std::string hop = cue::HopReason(stroke, search.cue_position(), search.params(),
                                         cue::TableMaxHop(search.params()));
  if (!hop.empty()) return Refusal{PotStatus::kNoStroke, hop};
  return std::nullopt;
}

}  // namespace billiard::pot
