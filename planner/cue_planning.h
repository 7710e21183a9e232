// The point planner with a robot's cue: the stroke that sends the ball to a point, played at the
// elevation the robot's cue needs to reach the ball over the rails, the other balls and its own
// body, and refused where no elevation does or where the ball would leave the cloth.
//
// The elevation is decided before the plan, as the pots decide theirs (planner/pot/
// cue_elevation.h): the least that clears along the closed form's first heading, plus
// cue::kElevationMargin (sim/cue/stroke_limits.h, where the margin is justified). The refinement
// then finds the launch at it (PlannerOptions::elevation: an elevated cue with side spin swerves
// the ball, and its stroke is the one at that elevation). The refined stroke, its heading turned
// by the squirt and the refinement, is checked again: where it meets something the plan is made
// once more at the elevation it needs there, and refused (cue_blocked) where it still does not
// clear. The request fixes the launch speed (the ball must arrive at its final speed), so there
// is no pace to choose: a stroke whose elevation would hop the ball beyond
// cue::kMaxHopOnTheCloth (the lone ball's 5-DOF run keeps it on the cloth) is
// refused (unreachable) with the hop and the fastest pace that would keep it down, and a stroke
// beyond the robot's own ranges (its speed, elevation, tip offset) is refused likewise.
//
// FastFiz (Archibald et al. 2010) checks the same of every stroke (isPhysicallyPossible) and
// refuses what fails it; sim/cue/clearance.h's rod is that check with the cue's thickness.
#pragma once

#include <vector>

#include "planner/shot_planner.h"
#include "sim/cue/robot.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner {

// Where the cue is checked: the robot, the table it plays on (the parameter set's size) and the
// balls besides the one struck (ids other than 0; the struck ball is the request's, id 0).
struct CueSetting {
  cue::Robot robot;
  table::TableGeometry table;
  std::vector<table::SceneBall> others;
};

// PlanShot at the elevation `setting`'s cue needs (above); the plan's `clearance` says how the
// final stroke clears. Never throws on a bad request: the status and reason say what is wrong.
ShotPlan PlanShotForRobot(const ShotRequest& request, const physics::ModelParameters& params,
                          const PlannerOptions& options, const CueSetting& setting);

}  // namespace billiard::planner
