// A robot's cue as a picture of the table shows it from above: the tapered rod from its tip on the
// cue ball back along the stroke's heading for the cue's length, where it comes nearest what it
// must clear (a ball, a rail, the cloth, the robot's own limits), and its elevation.
//
// Seen from above, a rod raised by e shows its axis foreshortened to L cos(e) and its full width
// at every point (a circle's cross-section is as wide from any side), so the outline is the
// trapezoid of the axis's ends on the table's plane, 2 r0 wide at the tip and 2 r1 at the butt.
// The caller places the cue (sim/cue/placed_cue.h) and finds its clearance (sim/cue/clearance.h);
// this module draws what it is given, so that it stays below sim/cue.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>

namespace billiard::plot {

struct CueOutline {
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();   // the axis's tip end on the table's plane [m]
  Eigen::Vector2d butt = Eigen::Vector2d::Zero();  // and its butt end [m]
  double tip_radius = 0, butt_radius = 0;          // the rod's [m]
  double elevation = 0;                            // [rad]
  // The point of the axis nearest the obstacle, on the table's plane, and the obstacle's name
  // and distance from the rod [m] (< 0: into it); no point when nothing is near (no clearance).
  std::optional<Eigen::Vector2d> nearest;
  std::string nearest_what;
  double distance = 0;
  std::optional<Eigen::Vector2d> obstacle;  // a ball's centre, when a ball comes nearest
};

// The outline's corners [m], counter-clockwise from the tip's left: tip + r0 n, butt + r1 n,
// butt - r1 n, tip - r0 n, n the left of the axis's direction from the butt to the tip.
std::array<Eigen::Vector2d, 4> OutlineCorners(const CueOutline& cue);

// The label beside the cue: "cue at 7.30 deg, clears ball 3 by 4.2 mm" ("cue level" at 0;
// "meets the lower rail, 1.5 mm into it" when it does not clear; the elevation alone without a
// clearance).
std::string CueLabel(const CueOutline& cue);

}  // namespace billiard::plot
