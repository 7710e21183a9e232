// The cue in place at the instant of a stroke's impact: its tip where the stroke's tip offsets
// put it on the cue ball, its axis along the stroke's heading and elevation, back to its butt.
//
// The placement is cue_strike.h's (Alciatore 2004, TP A.30): the cue's axis c points forward
// and down by the elevation, c = cos(elevation) e - sin(elevation) z with e the heading's
// horizontal unit vector; the tip offset b = tip_side n + tip_height u lies in the plane
// across c, with n = e x z the cue's horizontal right and u = n x c its up; the tip meets the
// ball at P = b - sqrt(r^2 - |b|^2) c from its centre (the near point of the sphere on the
// line through b along c). The cue's axis is that line, from P back along -c for the cue's
// length.
//
// The rod, for the distances (rod_distance.h), is the union of the balls of radius r(s)
// centred on the axis at s in [0, length] from the tip, r(s) growing linearly from tip_radius
// to butt_radius (a sphere-swept volume, Larsen et al. 2000, "Fast distance queries with
// rectangular swept sphere volumes", here with a radius that varies along the segment). With the
// taper k = dr/ds, its side lies at r(s) / sqrt(1 - k^2) from the axis, outside the truncated
// cone's r(s) by r k^2 / 2 to first order: 0.3 micrometres at the butt of a 1.47 m cue growing
// from 6.5 to 15.5 mm. Its ends are rounded: the tip's like a real tip's dome, the butt's
// reaching up to butt_radius past the cue's end (on the safe side). Whatever the rod touches,
// the truncated cone touches within those margins.
//
// Module: billiard::cue.
#pragma once

#include <Eigen/Core>

#include "sim/cue/robot.h"
#include "sim/physics/cue_strike.h"

namespace billiard::cue {

struct PlacedCue {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();    // P, in the table frame [m]
  Eigen::Vector3d back = Eigen::Vector3d::UnitX();  // unit, from the tip toward the butt (-c)
  CueShape shape;
  // The point of the axis `s` metres from the tip.
  Eigen::Vector3d At(double s) const { return tip + s * back; }
};

// The cue of `shape` placed for `stroke` (its heading, elevation and tip offsets; the speed is
// not read) on a ball of radius `ball_radius` resting at `ball_centre` on the cloth (its centre
// `ball_radius` above it). Throws std::invalid_argument on a non-finite number or a tip offset
// off the ball (|b| >= r), as physics::StrikeBall does.
PlacedCue PlaceCue(const Eigen::Vector2d& ball_centre, double ball_radius,
                   const physics::CueStroke& stroke, const CueShape& shape);

}  // namespace billiard::cue
