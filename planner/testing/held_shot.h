// A shot request on the paper's parameter set with the spin its closed-form launch chose held
// (HoldTheSpin, shot.h): where the tests of PlanShot's steps start. Header-only, for the tests.
#pragma once

#include <Eigen/Core>

#include "planner/closed_form_inverse.h"
#include "planner/shot.h"
#include "planner/shot_planner.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/parameters.h"

namespace billiard::planner::testing {

inline const physics::ModelParameters& Paper() {
  static const physics::ModelParameters p = params::LoadParameters("paper");
  return p;
}

// The request from `from` to `to`, its closed-form launch and the spin held, and the planner's
// options (the defaults until a test changes them). A Shot of it refers to its members.
struct HeldShot {
  ShotRequest q;
  LaunchSolution guess;
  HeldSpin held;
  PlannerOptions options;

  HeldShot(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double final_speed = 0.0,
           SpinStyle style = SpinStyle::kNatural, double side_spin = 0.0) {
    q.from = from;
    q.to = to;
    q.final_speed = final_speed;
    q.style = style;
    q.side_spin = side_spin;
    guess = InvertClosedForm(q, physics::ClosedFormParameters::From(Paper()));
    held = HoldTheSpin(q, guess, Paper());
  }
};

}  // namespace billiard::planner::testing
