// The elevation a stroke is played at with a robot's cue, and whether the ball it strikes stays
// on the cloth: the two limits every planner (the point planner, the pots, the safeties) holds a
// stroke to, kept here so that they hold it to the same ones.
//
// The elevation: the least that clears (clearance.h) plus kElevationMargin, decided before the
// aim, so that the aim and the motion simulate the stroke at the elevation it is played at (an
// elevated stroke with side spin squirts, swerves and drives the ball into the cloth,
// sim/physics/cue_strike.h). Why one degree: the aim turns the stroke's heading from the first
// guess the elevation was found at by up to a few tenths of a degree, the robot's heading noise
// by 0.1 degree (its standard deviation, sim/params/noise/robot.json) and the computational-pool
// noise tilts the cue by 0.1 degree; a degree raises the rod's point s behind the tip by
// s sin(1 deg), 2.6 mm at a gantry's carriage 0.15 m back, 8.7 mm at its butt, 26 mm at a
// player's 1.47 m, room for a turned heading's sideways sweep of the rod over an obstacle's
// rounded top. Where the margin would leave the robot's range, the range's top is used (it still
// clears). A cue that clears at the robot's lowest elevation is not raised: nothing lies under it.
//
// The hop: an elevated cue drives the ball into the slate, which returns e_b of the speed it was
// driven down with, v_down = v tan(elevation) for a launch v along the heading: the ball flies
// (e_b v_down)^2 / (2 g) high (sim/physics/hop.h). Each motion covers hops up to a height:
//  - the table's simulation flies the ball and lands it (sim/table/: airborne), taking its
//    contacts with other balls in the air as in the plane. A ball h above the cloth meets one at
//    rest with the line of centres asin(h / 2r) out of the plane: up to kMaxHopRadii, 2.9
//    degrees, and the planar impact's speed for it is 0.13 % too high (1 - cos), below the
//    robot's speed noise (1 %, sim/params/noise/robot.json); the part of the impulse into the
//    cloth (5 %) the cloth takes. A cushion meets a ball in the air lower on it, by its height
//    (sim/table/table_simulation.cc passes the height to the cushion's impact).
//  - a lone ball's 5-DOF run (the point planner, the table simulator's shots to a point) keeps
//    the ball on the cloth: kMaxHopOnTheCloth.
// The strike is linear in the cue speed (Alciatore 2004, TP A.30), so the hop grows with its
// square, and the fastest stroke of a shape within a motion's hop follows from one strike
// (HopFreeSpeed): the pace a planner may choose up to.
//
// Module: billiard::cue.
#pragma once

#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "sim/cue/clearance.h"
#include "sim/cue/robot.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/hop.h"
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {

// Above the least clearing elevation, for the aim's turn and the robot's noise (see above) [rad].
inline constexpr double kElevationMargin = M_PI / 180.0;
// The highest hop the table's simulation covers, in ball radii (see above).
inline constexpr double kMaxHopRadii = 0.1;
// The highest hop a motion that keeps the ball on the cloth is taken to cover [m]: a millimetre's
// flight lasts 2 sqrt(2 h / g) = 29 ms, about a tenth of a 2 m/s launch's slide on the pool
// cloth (2 v / (7 mu g) = 0.29 s), the friction the model applies during it then a small error.
inline constexpr double kMaxHopOnTheCloth = 1e-3;

// The highest hop [m] the table's simulation covers with `params`' balls: kMaxHopRadii radii.
double TableMaxHop(const physics::ModelParameters& params);

// The height [m] the ball would hop off the bed after `stroke` from `position` (0 for a level
// cue), with the bed's restitution physics::kBedRestitution.
double HopHeight(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                 const physics::ModelParameters& params);

// The fastest cue speed [m/s] at which `stroke`'s heading, tip offsets and elevation keep the
// hop within `max_hop` [m] (its speed is not read); infinity for a level cue.
double HopFreeSpeed(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                    const physics::ModelParameters& params, double max_hop);

// Why `stroke` would hop the ball beyond `max_hop` [m], in words ("the cue at 25.0 deg and 5.00
// m/s would hop the ball 8.16 mm, ..."); empty when it does not (within `max_hop` to the strike's
// rounding, which differs from heading to heading by a few ulps).
std::string HopReason(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                      const physics::ModelParameters& params, double max_hop);

// The elevation [rad] `stroke`'s heading and tip offsets are to be played at with `robot`, the
// cue ball (id `cue_ball_id`) and the other `balls` (of radius `ball_radius`) on `table`: the
// least that clears plus kElevationMargin (within the robot's range; no margin where the lowest
// clears), or the stroke's own where that is higher. When no elevation clears, the reason (what
// blocks at the range's top, by how much).
std::variant<double, std::string> ElevationFor(const table::TableGeometry& table, double ball_radius,
                                               const std::vector<table::SceneBall>& balls, int cue_ball_id,
                                               const physics::CueStroke& stroke, const Robot& robot);

}  // namespace billiard::cue
