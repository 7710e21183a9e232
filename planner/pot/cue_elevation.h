// The cue's step of a pot: the elevation a real cue needs to reach the cue ball over what lies
// behind it, and the check that the plan's final stroke can be made.
//
// A stroke the planner commands must be one the robot's cue can make (sim/cue/clearance.h: the
// cue as a tapered rod from its tip on the cue ball back along its axis, against every other
// ball, the cloth, the rails and the robot's own body). The elevation a stroke is planned with is
// the least that clears plus cue::kElevationMargin (sim/cue/stroke_limits.h, where the margin is
// justified), decided before the aim, so that the aim, the pace, the drop window and the truth
// all simulate the stroke at the elevation it is played at. The final stroke (its heading turned
// by the aim, its offsets by position play) is checked again.
//
// An elevated stroke drives the ball into the slate, which hops it: the table's simulation flies
// it (sim/physics/hop.h) up to a height (cue::TableMaxHop, a tenth of a radius, where its
// contacts in the air are still those of the plane): the pace and position play choose their
// cue speeds below TopCueSpeed, the fastest within it, so that a route is refused for the hop
// (no_stroke, with the hop in the reason) only when no pace within it pots.
//
// Module: billiard::pot.
#pragma once

#include <optional>
#include <variant>

#include "planner/pot/search_context.h"
#include "sim/cue/clearance.h"
#include "sim/cue/stroke_limits.h"

namespace billiard::pot {

// The fastest cue speed [m/s] for `shape` along `heading`: the cue's top speed
// (ModelParameters::cue.max_speed, and the robot's where there is one), or below it the fastest whose hop
// the table's motion covers (cue::HopFreeSpeed within cue::TableMaxHop) for an elevated cue.
double TopCueSpeed(const SearchContext& search, const StrokeShape& shape, double heading);

// The elevation [rad] `shape` is to be played at along `heading` with the search's robot: the
// least that clears plus cue::kElevationMargin (within the robot's range), or the shape's own where
// that is higher (a curve's). Without a robot (PotOptions::robot), the shape's own. A refusal
// (cue_blocked, what blocks at the range's top and by how much) when no elevation clears.
std::variant<double, Refusal> NeededElevation(const SearchContext& search, const StrokeShape& shape,
                                              double heading);

// The final stroke's check: it clears with the search's robot (cue_blocked where it does not,
// with the elevation it would need in Refusal::elevation_needed) and its hop is within cue::TableMaxHop
// (no_stroke where not). The clearance found, where there is a robot, in `*clearance`.
std::optional<Refusal> CheckCue(const SearchContext& search, const physics::CueStroke& stroke,
                                std::optional<cue::CueClearance>* clearance);

}  // namespace billiard::pot
