// A robot as data: the cue it holds, where it holds it, the strokes it can command (elevation,
// tip offset and speed ranges) and its body (a gantry's carriage over the table, an arm's base
// and reach), as sim/params/robots/*.json give them (params::LoadRobot reads and checks them).
//
// The cue is a rod tapering linearly from its tip to its butt (a "European" or conical taper,
// the shaft's usual shape; a "pro taper" keeps the tip's diameter for the first 30 cm, and is
// thinner there than the line, never thicker). The bridge is where the robot holds the cue, at
// impact, measured along the cue from its tip: a player's bridge hand, a gantry's carriage, an
// arm's gripper. The body is checked at the bridge and at the butt (body.h):
//  - a gantry's carriage runs over a rectangle reaching `overhang` beyond the cushion noses on
//    every side (the frame is built for its table) and comes no lower than `clearance`: the
//    height above the cloth of the cue's axis where the carriage holds it. The cue's butt must
//    stay within the rectangle too (the frame's beams stand at its edges).
//  - an arm's gripper must lie within `reach` of its base (a point in the table frame).
//  - a player has no body here: a person walks around the table.
//
// Module: billiard::cue. Includes the physics (sim/physics/) and Eigen.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "sim/physics/cue_strike.h"

namespace billiard::cue {

// The cue as a rod whose radius grows linearly from the tip to the butt.
struct CueShape {
  double length = 0;       // tip to butt [m]
  double tip_radius = 0;   // [m]
  double butt_radius = 0;  // [m], >= tip_radius
  // The radius `s` metres from the tip along the axis, 0 <= s <= length.
  double RadiusAt(double s) const { return tip_radius + Taper() * s; }
  // dr/ds, the growth of the radius per metre of the axis.
  double Taper() const { return (butt_radius - tip_radius) / length; }
};

struct Gantry {
  double overhang = 0;   // the carriage's rectangle beyond the cushion noses, every side [m]
  double clearance = 0;  // the least height of the cue's axis at the carriage above the cloth [m]
};

struct Arm {
  Eigen::Vector3d base = Eigen::Vector3d::Zero();  // in the table frame [m]
  double reach = 0;                                // from the base to the gripper [m]
};

// A closed interval.
struct Range {
  double min = 0, max = 0;
  bool Contains(double x) const { return x >= min && x <= max; }
};

struct Robot {
  std::string name;    // "gantry"
  std::string source;  // where every number comes from
  CueShape cue;
  double bridge = 0;          // from the cue's tip at impact to where the robot holds it [m]
  Range elevation;            // of the cue below the horizontal [rad], within [0, pi/2)
  double max_tip_offset = 0;  // the largest tip offset it commands, a fraction of the ball radius
  Range speed;                // of the cue at impact [m/s]
  std::optional<Gantry> gantry;  // at most one body; none for a player
  std::optional<Arm> arm;
  // Its execution noise: a built-in model's name or a noise file's path (params::LoadNoise).
  std::string noise;
};

// Throws std::invalid_argument with a one-line reason, naming the key of the robot files
// (sim/params/robots.h): "cue.butt_radius must be at least cue.tip_radius". Checks every number
// finite; the cue's length and radii positive, its butt no thinner than its tip and narrower
// than the cue is long; the bridge within the cue; 0 <= elevation min <= max < 90 degrees;
// max_tip_offset in (0, 1); 0 <= speed min <= max, max > 0; a gantry's overhang and clearance
// >= 0; an arm's reach > 0; at most one body.
void ValidateRobot(const Robot& robot);

// Why `stroke` is outside the robot's ranges (its elevation, its tip offset |(side, height)|
// against max_tip_offset times `ball_radius`, its speed), in words; empty when within them.
std::string OutsideRanges(const Robot& robot, const physics::CueStroke& stroke, double ball_radius);

}  // namespace billiard::cue
