// Step 3a of PlanShot (shot_planner.h): Newton's method on the launch speed alone.
//
// Turning the heading turns the whole path about the ball (the dynamics are isotropic in the
// plane), so a run at speed s, whatever its heading, says where every heading goes: its reach
// (distance from the ball) and its turn (the angle from the heading to the arrival) depend on s
// alone, and the heading that meets the target is the target's bearing minus the turn at the
// speed that reaches it. Both are modelled as quadratics in the launch's kinetic energy, e = s^2,
// rather than its speed: friction takes energy by the metre, so the reach is nearly linear in e
// (exactly so for a ball that rolls to rest), and what the quadratic misses is the little
// curvature left. The first run, with sensitivities (sim/physics/sensitivity.h), gives the values
// and the rates of change; each later run, without, the curvatures through it. On the
// benchmark's requests one or two corrections take the closed form's centimetres below the
// tolerance, where Gauss-Newton on (speed, heading) took two runs with sensitivities more.
#pragma once

#include "planner/shot.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {

// Aim's corrections before it hands over to Polish: from centimetres the second lands within
// the tolerance; needing more means the quadratic model does not hold there.
inline constexpr int kAimSteps = 3;

// Where a run arrives, seen from the ball: its distance from the ball, and the angle from the
// launch heading to the arrival's direction, in (-pi, pi].
struct Reach {
  double reach = 0.0, turn = 0.0;
};

// The reach of `arrival`, a run launched from `from` at `heading`.
Reach ReachOf(const physics::Arrival& arrival, const Eigen::Vector2d& from, double heading);

// The root nearest 0 of f + b x + c x^2 (b > 0); Newton's step where there is none.
double QuadraticRoot(double f, double b, double c);

// Corrects `launch` (speed, heading), the closed form's, for at most kAimSteps (and the options'
// max_iterations). Stops at a failed simulation or a speed beyond the bounds, `launch` at its
// last good run; returns the corrections made.
int Aim(Shot& shot, double launch[2]);

}  // namespace billiard::planner
