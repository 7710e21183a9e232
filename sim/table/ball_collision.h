// Two balls of equal mass and radius colliding: one instantaneous impulse at the contact point.
//
// The model of Alciatore's throw analysis (TP A.14, 2006): the normal impulse follows from the
// restitution e_b, J_n = (1 + e_b) m v_n / 2 (v_n the closing speed along the line of centres);
// friction between the balls acts against the slip of the two contact points, which the cut
// angle and every spin component make (side spin: spin-induced throw; follow and draw: the
// slip's vertical part, which lowers the throw), with a coefficient that falls with the slip
// speed, mu_b = a + b exp(-c v_rel) (his fit to Marlow's 1995 measurements). The friction
// impulse is mu_b J_n while the balls slip throughout, or the impulse that stops the slip
// (m |slip| / 7: each ball's contact point gives 1/m + r^2/I = 7 / (2 m)), whichever is smaller:
// the throw of TP A.14, min(mu_b v_n, |slip| / 7 (1 + e_b) / 2)-shaped. Friction never reverses
// the slip, so the impulse never adds energy; the impulses on the two balls are opposite, so
// momentum is conserved exactly. The balls stay on the cloth: the friction's vertical part turns
// their spins but not their centres.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"

namespace billiard::table {

struct BallBallImpulse {
  physics::BallState a, b;            // the two balls just after the impact
  double normal = 0.0;                // J_n [N s], along the line of centres from a to b
  double friction = 0.0;              // |J_t| [N s], in the contact's tangent plane
  double friction_coefficient = 0.0;  // mu_b at the slip speed before the impact
};

// The impact of balls a and b touching (centres 2 r apart). Balls that do not close (v_n <= 0)
// are returned unchanged with no impulse.
BallBallImpulse ResolveBallBallImpact(const physics::BallState& a, const physics::BallState& b,
                                      const physics::BallParameters& ball,
                                      const physics::CollisionParameters& collision);

// Alciatore's speed-dependent ball-ball friction, mu_b = a + b exp(-c v_rel).
double BallBallFriction(const physics::CollisionParameters& collision, double slip_speed);

}  // namespace billiard::table
