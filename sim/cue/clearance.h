// Whether a real cue can play a stroke: the robot's cue placed for the stroke (placed_cue.h),
// a rod tapering from its tip on the cue ball back along its axis for its length, against every
// other ball, the cloth and the rails (table_obstacles.h), and the robot's own body (body.h);
// and the least elevation at which it can.
//
// A stroke clears when the rod keeps a distance > 0 from every obstacle; touching is blocked.
// The cue ball itself is no obstacle (the tip meets it). The clearance names the obstacle that
// comes nearest and its distance: what blocks, and by how much, when the stroke does not clear;
// how much room is left when it does.
//
// The least clearing elevation, for a heading and tip offsets, searches the robot's elevation
// range. What a stroke meets lies behind the cue ball, below the cue: raising the cue lifts
// every point of the rod behind its tip (the point s from the tip by s sin(elevation), the tip
// itself up the ball) and draws it in (by s (1 - cos(elevation))), so a ball, a rail, the cloth or
// a gantry's limit that clears at one elevation clears at the higher ones (every analytic case of
// the tests is so), and bisection finds the least to any resolution. Not every limit is so: an
// arm's gripper moves on an arc as the cue rises, and may leave the arm's reach. So the range is first scanned upward in steps of
// half a degree for the first elevation that clears, then the step below it bisected to 1e-9
// rad. A window that clears below the first clear step and is narrower than a step is missed:
// the elevation found is then above the least, and still clears (the search only ever returns
// an elevation it found clear).
//
// FastFiz (Archibald et al. 2010, "Computational pool: a new challenge for game theory
// pragmatics", its TableState::isPhysicallyPossible) checks a line 1.45 m long from the tip
// against the balls and a 0.040 m rail where the line crosses the table's edge; this is that
// check with the cue's thickness and taper, the rail's width, and the robot's body.
//
// Module: billiard::cue.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sim/cue/robot.h"
#include "sim/physics/cue_strike.h"
#include "sim/table/scene.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {

enum class Obstacle { kNone, kBall, kTable, kBody };

struct CueClearance {
  bool clears = false;                 // the rod keeps a distance > 0 from everything
  Obstacle nearest = Obstacle::kNone;  // what comes nearest (what blocks, when it does not clear)
  int ball = -1;                       // its id, for kBall
  // In words: "ball 3", "the cloth", "the lower rail" (table_obstacles.h), "the carriage below
  // its clearance" (body.h); empty for kNone (nothing on the table and no body).
  std::string what;
  double distance = std::numeric_limits<double>::infinity();  // from the rod to it [m]; < 0 overlap
  // Where the rod comes nearest it: the point of the cue's axis so far from the tip [m] (where
  // the cue clears it, or meets it).
  double along = 0;
};

// The clearance of `stroke` (its heading, elevation and tip offsets; the speed is not read)
// played on the ball `cue_ball_id` of `balls` (at its position; balls of radius `ball_radius`,
// resting on the cloth) with `robot`'s cue and body on `table`. Throws std::invalid_argument
// when `balls` has no ball `cue_ball_id`, or on a stroke physics::StrikeBall refuses for its
// placement (a non-finite number, a tip offset off the ball).
CueClearance Clearance(const table::TableGeometry& table, double ball_radius,
                       const std::vector<table::SceneBall>& balls, int cue_ball_id,
                       const physics::CueStroke& stroke, const Robot& robot);

struct ClearingElevation {
  std::optional<double> elevation;  // the least in the robot's range that clears [rad]
  // Why none, when there is none: "nothing in the robot's elevations [0, 60] deg clears: at
  // 60 deg ball 3 is 2.1 mm into the cue".
  std::string reason;
  CueClearance clearance;  // at `elevation`; at the range's top when there is none
};

// The least elevation within robot.elevation at which `stroke`'s heading and tip offsets clear
// (its elevation is not read), as the search above finds it; Clearance's arguments otherwise.
ClearingElevation LeastClearingElevation(const table::TableGeometry& table, double ball_radius,
                                         const std::vector<table::SceneBall>& balls,
                                         int cue_ball_id, const physics::CueStroke& stroke,
                                         const Robot& robot);

}  // namespace billiard::cue
