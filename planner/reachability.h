// Where the planner's reach ends (PlanShot, shot_planner.h): the playing surface, the spin a
// stroke can give, and the distance the launch speed bounds carry the ball.
//
// Turning the heading turns the whole path about the ball, so how far the ball gets depends on
// the launch speed alone, and grows with it. The bounds on the speed (tip offset within
// max_tip_offset r for the spin asked, cue speed within max_speed; LaunchSpeedsFor in
// sim/physics/cue_strike.h) therefore decide reachability with one simulation at the bound.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "planner/closed_form_inverse.h"
#include "planner/shot.h"
#include "sim/physics/parameters.h"

namespace billiard::planner {

// Whether a ball centred at `x` is on the playing surface of `p`'s table (a radius inside every
// edge, the edge itself included).
bool OnTable(const Eigen::Vector2d& x, const physics::ModelParameters& p);

// The refusal of a spin R w / v = `spin_ratio` across the line, with `q`'s side spin, that no
// stroke within the robot's tip offset and cue speed gives.
std::string NoStrokeGivesTheSpin(double spin_ratio, const ShotRequest& q,
                                 const physics::ModelParameters& params);

// A speed at a bound that already carries the ball past the target (or still leaves it short)
// decides the request without a refinement: the reason, or nullopt when `speed` is within the
// bounds or the bound's run (simulated once) reaches the target within the acceptable miss.
std::optional<std::string> BeyondReach(Shot& shot, double speed, double heading);

}  // namespace billiard::planner
