// The closed-form sliding-then-rolling model of Jaroukh 2019, in two dimensions.
//
// Point contact with Coulomb friction mu_s while the contact point slips, then rolling without
// slip decelerated by rolling resistance mu_r until rest. Both phases are solved exactly, so the
// model needs no integration: the state at any time is a quadratic polynomial of the phase time.
// The seed's misprints are corrected (I = 2/5 m R^2; eq. 15: t2 = t1 + 7 (|v1| - v2) / (5 mu_r g)).
//
// A point contact exerts no moment about the normal, so wz keeps its initial value for ever;
// the 5-DOF model (ball_dynamics.h) is the one to use when pivot friction matters.
#pragma once

#include <Eigen/Core>
#include <limits>

#include "sim/physics/parameters.h"
#include "sim/physics/trajectory.h"

namespace billiard::physics {

struct ClosedFormParameters {
  double radius = 0.0;    // R [m]
  double gravity = 0.0;   // g [m/s^2]
  double mu_slide = 0.0;  // mu_s
  double mu_roll = 0.0;   // mu_r

  // mu_s = mu, mu_r = a d / (5 r): the limit of the 5-DOF model (physics notes, section 2).
  static ClosedFormParameters From(const ModelParameters& p);
};

class ClosedFormTrajectory : public Trajectory {
 public:
  ClosedFormTrajectory(const ClosedFormParameters& p, const BallState& initial);

  BallState At(double t) const override;
  double start_time() const override { return 0.0; }
  // The time the ball comes to rest (infinite when mu_r = 0 and it rolls).
  double end_time() const override { return stop_time_; }

  double slide_end_time() const { return slide_end_time_; }  // t1 = 2 |u0| / (7 mu_s g), eq. 8
  double stop_time() const { return stop_time_; }            // t2, eq. 15 with v2 = 0
  // The first time the speed falls to `speed` (0 for a ball already that slow; infinite if it
  // never does).
  double TimeAtSpeed(double speed) const;
  // The state at the end of sliding (x1, v1 of eqs. 9-10).
  const BallState& slide_end_state() const { return slide_end_; }

 private:
  BallState Sliding(double t) const;
  BallState Rolling(double tau) const;

  ClosedFormParameters p_;
  BallState initial_;
  Eigen::Vector2d slip_direction_ = Eigen::Vector2d::Zero();  // u0 / |u0|
  Eigen::Vector2d roll_direction_ = Eigen::Vector2d::Zero();  // v1 / |v1|
  double slide_end_time_ = 0.0;
  double stop_time_ = std::numeric_limits<double>::infinity();
  BallState slide_end_;
};

}  // namespace billiard::physics
