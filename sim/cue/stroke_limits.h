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
// The hop: the strike model keeps the ball on the cloth (the table takes the vertical momentum an
// elevated cue gives). A real ball hops: it leaves the slate with the restitution e_t of the bed
// times the speed it was driven down with, v_down = v tan(elevation) for a launch v along the
// heading, and flies (e_t v_down)^2 / (2 g) high. A stroke whose hop would exceed kMaxHop is one
// the model does not cover. The strike is linear in the cue speed (Alciatore 2004, TP A.30), so
// the hop grows with its square, and the fastest stroke of a shape that stays within kMaxHop
// follows from one strike (HopFreeSpeed): the pace a planner may choose up to.
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
#include "sim/physics/parameters.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {

// Above the least clearing elevation, for the aim's turn and the robot's noise (see above) [rad].
inline constexpr double kElevationMargin = M_PI / 180.0;
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

// The fastest cue speed [m/s] at which `stroke`'s heading, tip offsets and elevation keep the
// hop within kMaxHop (its speed is not read); infinity for a level cue.
double HopFreeSpeed(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                    const physics::ModelParameters& params);

// Why `stroke` would hop the ball beyond kMaxHop, in words ("the cue at 25.0 deg would lift the
// ball off the cloth (a hop of 8.16 mm, ...)"); empty when it stays on the cloth (within kMaxHop
// to the strike's rounding, which differs from heading to heading by a few ulps).
std::string HopReason(const physics::CueStroke& stroke, const Eigen::Vector2d& position,
                      const physics::ModelParameters& params);

// The elevation [rad] `stroke`'s heading and tip offsets are to be played at with `robot`, the
// cue ball (id `cue_ball_id`) and the other `balls` (of radius `ball_radius`) on `table`: the
// least that clears plus kElevationMargin (within the robot's range; no margin where the lowest
// clears), or the stroke's own where that is higher. When no elevation clears, the reason (what
// blocks at the range's top, by how much).
std::variant<double, std::string> ElevationFor(const table::TableGeometry& table, double ball_radius,
                                               const std::vector<table::SceneBall>& balls, int cue_ball_id,
                                               const physics::CueStroke& stroke, const Robot& robot);

}  // namespace billiard::cue
