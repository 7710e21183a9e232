// A ball's motion on the cloth between two events: in closed form, or by the 5-DOF model.
//
// The point-contact model of Jaroukh 2019 (`sim/physics/closed_form.h`): Coulomb friction mu_s
// while the contact point slips, then rolling without slip decelerated by rolling resistance
// mu_r; to it the table adds the pivot friction of the contact patch, which the 5-DOF model of
// Kudra et al. 2016 has and a point contact lacks: the spin wz decays at the constant rate
// 5/2 g a mu Ms / r^2, Ms = 3 pi / 16 the moment of a uniformly slipping disk (pure spin, eq. 16;
// physics notes, section 1), whatever the ball's translation does. So a ball passes through
// sliding, rolling, spinning in place and rest, each phase a polynomial in time: the centre moves
// on a parabola (constant acceleration), which is what makes every collision time the root of a
// polynomial (`sim/table/polynomial_roots.h`).
//
// The 5-DOF model of Kudra et al. 2016 (`sim/physics/simulator.h`) is the other motion a ball
// may have between events: its friction acts over the contact patch, so it has what the point
// contact lacks (rolling resistance while the ball slides, side spin curving the path), at the
// cost of an integration. Its segment runs until the ball rests (the rest switch of
// `sim/physics/rest.h`); its centre's path is no polynomial, so the simulation finds its
// contacts by conservative advancement, from the bound on how fast it can move.
//
// Off the cloth (`sim/physics/hop.h`: a ball an elevated cue has struck hops), a ball flies: its
// centre moves straight at constant velocity, its spin keeps, until it lands; the landing is a
// transition like the others (the bed's impulse, then the next bounce or the cloth).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <memory>

#include "sim/physics/ball_state.h"
#include "sim/physics/hop.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"
#include "sim/physics/trajectory.h"

namespace billiard::table {

// kFiveDof: moving by the 5-DOF model (sliding and rolling alike), until it rests. kAirborne:
// off the cloth, until it lands.
enum class MotionPhase { kSliding, kRolling, kSpinning, kStationary, kFiveDof, kAirborne };

const char* PhaseName(MotionPhase phase);

// The cloth as the closed form sees it.
struct ClothParameters {
  double radius = 0.0;      // r [m]
  double gravity = 0.0;     // g [m/s^2]
  double mu_slide = 0.0;    // mu_s = mu
  double mu_roll = 0.0;     // mu_r = a d / (5 r)
  double spin_decel = 0.0;  // |dwz/dt| = 5/2 g a mu (3 pi / 16) / r^2 [rad/s^2]

  static ClothParameters From(const physics::ModelParameters& p);
};

// A slip above this is a slide; below it, the regularized 5-DOF contact's residue of one, or a
// ball the closed form rolls.
inline constexpr double kSlideSlip = 1e-3;  // [m/s]

// The closed form's phase of a ball in state s: sliding while its contact point slips, rolling
// while it moves, spinning in place while wz turns, else stationary (never kFiveDof).
MotionPhase PhaseOf(const physics::BallState& s, double radius);

// One phase of a ball's motion, from `start_time` to `end_time` (the next transition; infinite
// for a ball at rest). Times are the table's; the polynomial's variable is tau = t - start_time.
class MotionSegment {
 public:
  // The phase a ball in `state` is in, and its motion from `start_time` until the phase ends.
  MotionSegment(const ClothParameters& cloth, double start_time, const physics::BallState& state);

  // A ball held in contact (`sim/table/held_contacts.h`): its centre moves with the constant
  // `acceleration` that the cloth and the contact forces give it, its spin as in its phase
  // (PhaseOf; a ball at rest that the forces move rolls), until the first of `longest` later,
  // the least of its slip (sliding: the slip's direction is taken as fixed, so it ends there)
  // and the turn of its velocity (the forces that oppose its direction, rolling resistance and a
  // cushion's friction, would drive it past that: rolling, at its least speed; sliding, where it
  // turns square to its first direction). No phase end is snapped to: the contact forces are
  // solved again at the end.
  MotionSegment(const ClothParameters& cloth, double start_time, const physics::BallState& state,
                const Eigen::Vector2d& acceleration, double longest);

  // The 5-DOF model with `options` from `start_time` until the ball rests, or `horizon` later.
  // At its end the ball is at rest (v = 0, w_xy = 0; wz as the model left it) unless the horizon
  // came first.
  MotionSegment(const physics::ModelParameters& params, const physics::SimulationOptions& options,
                double start_time, const physics::BallState& state, double horizon);

  // A ball off the cloth in `flight` (physics::Airborne): straight at constant velocity and
  // spin until it lands.
  MotionSegment(const ClothParameters& cloth, double start_time, const physics::BallState& state,
                const physics::Flight& flight);

  // Whether the centre moves on a parabola (position(), velocity(), acceleration() hold).
  bool closed_form() const { return trajectory_ == nullptr; }
  // Whether the motion is that of a ball held in contact.
  bool held() const { return held_; }

  MotionPhase phase() const { return phase_; }
  double start_time() const { return start_time_; }
  double end_time() const { return end_time_; }
  const physics::BallState& start_state() const { return start_; }

  // The state at table time t, start_time <= t <= end_time (clamped to the segment).
  physics::BallState At(double t) const;

  // The ball's flight at table time t (clamped to the segment); none (on the cloth) but in
  // kAirborne.
  physics::Flight FlightAt(double t) const;

  // A bound on the centre's acceleration over the segment [m/s^2].
  double max_acceleration() const { return max_acceleration_; }

  // The centre's position as p0 + v0 tau + 1/2 a tau^2 (closed form only).
  Eigen::Vector2d position() const { return start_.segment<2>(physics::kX); }
  Eigen::Vector2d velocity() const { return start_.segment<2>(physics::kVx); }
  const Eigen::Vector2d& acceleration() const { return acceleration_; }

 private:
  void StopSpinAt();  // sets spin_stop_ from the start state's wz

  ClothParameters cloth_;
  MotionPhase phase_;
  double start_time_;
  double end_time_ = std::numeric_limits<double>::infinity();
  double spin_stop_ = 0.0;  // tau at which wz reaches 0
  physics::BallState start_;
  Eigen::Vector2d acceleration_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d slip_direction_ = Eigen::Vector2d::Zero();  // sliding: u / |u|
  double max_acceleration_ = 0.0;
  bool held_ = false;
  physics::Flight flight_;                                 // kAirborne: at the start
  std::shared_ptr<const physics::Trajectory> trajectory_;  // the 5-DOF motion, from tau = 0
  physics::BallState end_ = physics::BallState::Zero();    // the 5-DOF motion's last state
};

using physics::ClothSlip;

}  // namespace billiard::table
