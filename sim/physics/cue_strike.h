// The cue striking the ball: from what the robot arm does (cue speed, heading, tip offsets,
// elevation) to the ball's launch state, and back.
//
// Model: Alciatore, The Illustrated Principles of Pool and Billiards (2004), TP A.30 (the impulse
// along the cue) and TP A.31 (squirt). The tip meets the ball at the point P of its surface on the
// cue axis c, offset by b (perpendicular to c) from the centre: P = b - sqrt(r^2 - b^2) c. Along c
// the whole cue (mass M) takes part in the impact; sideways, along the cue's horizontal right n,
// only the shaft's tip end (the end mass m_e). The impulse on the ball, J = J_c c + J_n n, meets
// two conditions at separation: along c the contact points part at e V (the tip's restitution e,
// TP A.30); along n the tip end moves with the ball's contact point (the tip grips, TP A.31). With
// the ball's inverse mass at P, (7/2 - 5/2 p p^T) / m (p = P / r), q = |b| / r, q_n = b . n / r:
//
//     [1/M + (1 + 5/2 q^2)/m       5/2 q_n sqrt(1 - q^2)/m       ] [J_c]   [(1 + e) V]
//     [5/2 q_n sqrt(1 - q^2)/m     1/m_e + (1 + 5/2 (1 - q_n^2))/m] [J_n] = [0        ],
//
// so the ball leaves a level cue turned by the squirt angle alpha (TP A.31's formula for q = q_n):
//
//     tan(alpha) = -J_n / J_c = 5/2 q_n sqrt(1 - q^2) / (1 + m/m_e + 5/2 (1 - q_n^2)),
//
// away from the side struck (right english squirts the ball left, counterclockwise seen from
// above). Velocity and spin both come from this one impulse, v = J / m and w = P x J / I
// (I = 2/5 m r^2): the sideways push also takes a little of the side spin. Without a side offset
// J_n = 0 and J_c = (1 + e) M m V / (m + M (1 + 5/2 q^2)), TP A.30 exactly. The impact takes
// (1 - e) V J_c / 2 of kinetic energy from cue (M along c, m_e sideways) and ball: with e = 1 it
// keeps the energy at any offset.
//
// An elevated cue (c pointing down by `elevation`) also pushes the ball into the cloth: the table
// takes the vertical momentum (the ball stays on the cloth); its friction during the impact is
// neglected. Not modelled: a grip of the tip end in the cue's up direction (no squirt from a
// vertical offset; top and draw are TP A.30's). Tip friction is assumed to hold (no miscue)
// within max_tip_offset.
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

// The ball's state right after the stroke, at `position`. The launch direction is the heading
// turned by the squirt; throws std::invalid_argument on a stroke no cue gives.
BallState StrikeBall(const CueStroke& stroke, const Eigen::Vector2d& position,
                     const ModelParameters& p);

// TP A.31's squirt angle of a level stroke with the tip `tip_side` [m] right of centre at centre
// height: the angle [rad] from the cue's heading to the launch, counterclockwise (so > 0 for
// right english). Throws std::invalid_argument if |tip_side| >= r.
double SquirtAngle(double tip_side, const ModelParameters& p);

struct StrokeSolution {
  bool ok = false;
  std::string reason;  // why not, when !ok
  CueStroke stroke;
};

// The stroke that launches the ball with velocity v0 (horizontal) and spin w0, squirt included:
// the heading is off v0 by the squirt angle. The impulse and the contact point follow from v0 and
// w0 (w0 = P x J / I is perpendicular to J, which fixes the vertical part of J the table took and
// so the elevation; a level cue leaves no spin about the travel); the squirt angle is the root of
// one equation (bisection, to the last bit). Without side spin w0 leaves the elevation free (an
// elevated cue struck above or below centre gives the same launch with a smaller offset and a
// faster cue, the table taking the rest): `free_slope` is then the vertical part of the impulse
// per unit of its horizontal part, tan(elevation); 0, a level cue. With side spin the spin about
// the travel fixes it (wz free_slope for a launch planned at that slope). Fails (with the reason)
// on non-finite input, a negative slope, v0 = 0, spin no stroke can give, a tip offset beyond
// max_tip_offset r, or a cue speed beyond max_speed.
StrokeSolution StrokeFor(const Eigen::Vector2d& v0, const Eigen::Vector3d& w0,
                         const ModelParameters& p, double free_slope = 0.0);

// The launch speeds a level stroke can give a ball sent along a line with spin R w = k v about the
// horizontal axis across the line and side spin wz, squirt included: bounded below by the tip
// offset that spin needs (within max_tip_offset r; where the slowest such launch needs a cue
// speed beyond max_speed, by the cue speed) and above by the cue speed (within max_speed). min >
// max when no stroke gives that spin.
struct LaunchSpeedRange {
  double min = 0.0, max = 0.0;
};
LaunchSpeedRange LaunchSpeedsFor(double spin_ratio, double side_spin, const ModelParameters& p);

}  // namespace billiard::physics
