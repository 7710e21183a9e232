// Balls held in contact: the contact forces of touching bodies pressed together by their
// accelerations (a ball pushed by another, a cue ball following through a frozen ball, a ball
// driven into a cushion by its spin, a cluster pushed as one), instead of a run of tiny impacts.
//
// Each ball answers a force through its centre as the closed form's point contact does
// (`sim/table/ball_motion.h`; Jaroukh 2019):
//  - sliding: the cloth's friction is fixed by the slip (mu_s g against it), so the force adds
//    to the centre's acceleration whole and leaves the spin alone;
//  - rolling: the ball keeps rolling (the cloth's friction turns it), so 5/7 of the force moves
//    the centre (a solid sphere's m / (m + I / r^2)), less the rolling resistance against its
//    velocity;
//  - at rest (or spinning in place): it starts to roll once 5/7 of the force passes its rolling
//    resistance, and holds below that.
// A contact only pushes, and only as hard as it must to keep its bodies from closing: the
// normal forces solve a linear complementarity problem (the forces nonnegative, the bodies'
// closing accelerations nonpositive, one of the two zero at each contact), by projected
// Gauss-Seidel (projected SOR with unit relaxation: Cottle, Pang & Stone 1992, section 5.2),
// which handles the balls at rest as they are, not linearized. A cushion or a jaw is a body that
// does not move, whose friction (mu_w of the parameter set) opposes the ball's sliding along it.
// Touching bodies that close at a speed below an impact's (`kSlowImpact`) first meet plastically
// (the same solve on velocities, with impulses for forces), and bodies that part slower than
// 1e-5 m/s are stopped, so that a held contact starts with its bodies moving together along its
// normal and its force does no work: the energy of such speeds (below 1e-9 J) is nothing, and an
// impact would part the bodies for nanoseconds only.
//
// The contact normals are taken as fixed over a held motion: balls held in contact that slide
// past each other part (their centres' distance grows as the square of the time, never shrinks),
// so the table limits a held motion to the time in which they part by `kHoldGap / 2` and then
// solves the contacts again.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/physics/ball_state.h"
#include "sim/table/ball_motion.h"

namespace billiard::table {

// Bodies nearer than this are in contact for the held-contact solve: a held motion lets touching
// balls part by half of it before the contacts are solved again.
inline constexpr double kHoldGap = 1e-7;  // [m]

struct HeldContact {
  int a = -1;                                  // a ball of the cluster
  int b = -1;                                  // the other ball, or -1: a cushion or jaw
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // unit, from a's centre toward b
  double friction = 0.0;                       // a cushion's or jaw's Coulomb friction
};

struct HeldSolution {
  std::vector<physics::BallState> states;      // after the plastic meeting of slow closings
  std::vector<Eigen::Vector2d> accelerations;  // each centre's, with the contact forces
  std::vector<Eigen::Vector2d> forces;         // the contact forces on each ball, per unit mass
  std::vector<double> normal_forces;           // per contact, per unit mass [m/s^2]
  double residual = 0.0;  // the largest closing acceleration left at a contact [m/s^2]
};

// The contact forces of a cluster of balls in `states` touching along `contacts` (every one of
// them closing no faster than kSlowImpact: a faster one is an impact, the caller's).
HeldSolution SolveHeldContacts(const ClothParameters& cloth, std::vector<physics::BallState> states,
                               const std::vector<HeldContact>& contacts);

}  // namespace billiard::table
