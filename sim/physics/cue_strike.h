// The cue striking the ball: from what the robot arm does (cue speed, heading, tip offsets,
// elevation) to the ball's launch state, and back.
//
// Model: Alciatore, The Illustrated Principles of Pool and Billiards (2004), TP A.30. The tip
// delivers an impulse J along the cue axis c through a point offset by b (perpendicular to c)
// from the ball centre; with cue mass M, ball mass m, tip restitution e and cue speed V,
//
//     J = (1 + e) M m V / (m + M (1 + 5/2 q^2)),   q = |b| / r,
//     v = J c / m,   w = 5 J (b x c) / (2 m r^2),
//
// so v = (1 + e) V / (1 + m / M + 5/2 q^2): the tip meets the ball's effective mass at the
// contact, m / (1 + 5/2 q^2), and with e = 1 the kinetic energy of cue and ball is conserved at
// any offset.
//
// An elevated cue (c pointing down by `elevation`) also pushes the ball into the cloth: the table
// takes the vertical momentum (the ball stays on the cloth); its friction during the impact is
// neglected. Tip friction is assumed to hold (no miscue) within max_tip_offset.
#pragma once

#include <Eigen/Core>
#include <string>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"

namespace billiard::physics {

struct CueStroke {
  double speed = 0.0;       // V, cue speed at impact [m/s]
  double heading = 0.0;     // direction of the cue's horizontal projection [rad from +x]
  double tip_side = 0.0;    // tip offset to the right of the cue axis [m] (right english > 0)
  double tip_height = 0.0;  // tip offset above the cue axis's centre line [m] (follow > 0)
  double elevation = 0.0;   // cue angle below the horizontal [rad], 0 <= elevation < pi/2
};

// The ball's state right after the stroke, at `position`.
BallState StrikeBall(const CueStroke& stroke, const Eigen::Vector2d& position,
                     const ModelParameters& p);

struct StrokeSolution {
  bool ok = false;
  std::string reason;  // why not, when !ok
  CueStroke stroke;
};

// The stroke that launches the ball with velocity v0 (horizontal) and spin w0. The spin must be
// perpendicular to the cue axis, which fixes the elevation: tan(elevation) = (w0 . v0_hat) / wz.
// Fails (with the reason) on non-finite input, v0 = 0, spin no stroke can give, a tip offset
// beyond max_tip_offset r, or a cue speed beyond max_speed.
StrokeSolution StrokeFor(const Eigen::Vector2d& v0, const Eigen::Vector3d& w0,
                         const ModelParameters& p);

// The launch speeds a level stroke can give a ball sent along a line with spin R w = k v about the
// horizontal axis across the line and side spin wz: bounded below by the tip offset that spin
// needs (within max_tip_offset r) and above by the cue speed (within max_speed). min > max when
// no stroke gives that spin.
struct LaunchSpeedRange {
  double min = 0.0, max = 0.0;
};
LaunchSpeedRange LaunchSpeedsFor(double spin_ratio, double side_spin, const ModelParameters& p);

}  // namespace billiard::physics
