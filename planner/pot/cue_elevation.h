// The cue's step of a pot: the elevation a real cue needs to reach the cue ball over what lies
// behind it, and the check that the plan's final stroke can be made.
//
// A stroke the planner commands must be one the robot's cue can make (sim/cue/clearance.h: the
// cue as a tapered rod from its tip on the cue ball back along its axis, against every other
// ball, the cloth, the rails and the robot's own body). The elevation a stroke is planned with is
// the least that clears (cue::LeastClearingElevation) plus kElevationMargin, decided before the
// aim, so that the aim, the pace, the drop window and the truth all simulate the stroke at the
// elevation it is played at: an elevated stroke with side spin squirts, swerves and drives the
// ball into the cloth (sim/physics/cue_strike.h), and the aim is found with that. The final
// stroke (its heading turned by the aim, its offsets by position play) is checked again.
//
// Why one degree: the aim turns the stroke's heading from the first guess the elevation was
// found at by up to a few tenths of a degree, the robot's heading noise by 0.1 degree (its
// standard deviation, sim/params/noise/robot.json) and the computational-pool noise tilts the
// cue by 0.1 degree; a degree raises the rod's point s behind the tip by s sin(1 deg), 2.6 mm at
// a gantry's carriage 0.15 m back, 8.7 mm at its butt, 26 mm at a player's 1.47 m, room for a
// turned heading's sideways sweep of the rod over an obstacle's rounded top. Where the margin
// would leave the robot's range, the range's top is used (it still clears). A cue that clears
// at the robot's lowest elevation is not raised: nothing lies under it to be raised over, and
// the final check catches a turned heading that meets something.
//
// The strike model keeps the ball on the cloth: the table takes the vertical momentum an
// elevated cue gives (cue_strike.h). A real ball hops: it leaves the slate with the restitution
// e_t of the bed times the speed it was driven down with, v_down = v tan(elevation) for a launch
// v along the heading, and flies (e_t v_down)^2 / (2 g) high, without friction. A stroke whose
// hop would exceed kMaxHop is one the model does not cover: it is refused (no_stroke) with the
// hop in the reason, not played as if the ball stayed down.
//
// Module: billiard::pot.
#pragma once

#include <optional>
#include <variant>

#include "planner/pot/search_context.h"
#include "sim/cue/clearance.h"

namespace billiard::pot {

// Above the least clearing elevation, for the aim's turn and the robot's noise (see above).
inline constexpr double kElevationMargin = 1.0 * kDegree;
// The slate bed's restitution under a cloth: an assumption of about a half (the bed takes most
// of the ball's downward speed; not measured here).
inline constexpr double kBedRestitution = 0.5;
// The highest hop the model's ball-on-the-cloth is taken to cover [m]: a millimetre's flight
// lasts 2 sqrt(2 h / g) = 29 ms, about a tenth of a 2 m/s launch's slide on the pool cloth
// (2 v / (7 mu g) = 0.29 s), the friction the model applies during it then a small error.
inline constexpr double kMaxHop = 1e-3;

// The height [m] the ball would hop off the bed after `stroke` from `position` (0 for a level
// cue), with the bed's restitution kBedRestitution.
double HopHeight(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                 const physics::ModelParameters& params);

// The elevation [rad] `stroke`'s heading and tip offsets are to be played at with `robot`, the
// cue ball (id 0) and the other `balls` (of radius `ball_radius`) on `table`: the least that
// clears plus kElevationMargin (within the robot's range; no margin where the lowest clears),
// or the stroke's own where that is higher. When no elevation clears, the reason (what blocks at the range's top, by how much).
std::variant<double, std::string> ElevationFor(const table::TableGeometry& table, double ball_radius,
                                               const std::vector<table::SceneBall>& balls,
                                               const physics::CueStroke& stroke, const cue::Robot& robot);

// The elevation [rad] `shape` is to be played at along `heading` with the search's robot: the
// least that clears plus kElevationMargin (within the robot's range), or the shape's own where
// that is higher (a curve's). Without a robot (PotOptions::robot), the shape's own. A refusal
// (cue_blocked, what blocks at the range's top and by how much) when no elevation clears.
std::variant<double, Refusal> NeededElevation(const SearchContext& search, const StrokeShape& shape,
                                              double heading);

// The final stroke's check: it clears with the search's robot (cue_blocked where it does not,
// with the elevation it would need in Refusal::elevation_needed) and its hop is within kMaxHop
// (no_stroke where not). The clearance found, where there is a robot, in `*clearance`.
std::optional<Refusal> CheckCue(const SearchContext& search, const physics::CueStroke& stroke,
                                std::optional<cue::CueClearance>* clearance);

}  // namespace billiard::pot
