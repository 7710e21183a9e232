// `--model auto`: the cheapest model and integrator whose measured error on this kind of scene
// stays within the requested accuracy.
//
// The table is docs/benchmarks/model_choice.json, written by `billiard bench` and compiled into
// the library: per scene kind, every benchmarked method's median time per 8 s shot and its p95
// endpoint distance from the integral model converged (the most faithful model here).
//
// Module: billiard::model_choice. Includes the physics (sim/physics/) and the table's motion
// rule (sim/table/).
#pragma once

#include <string>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"
#include "sim/table/table_simulation.h"

namespace billiard::model_choice {

// "rolling": no side spin and no slip at the start (the closed form is exact up to the
// regularization); "sliding": no side spin; "side-spin": wz != 0 (the closed form has no side
// spin, so it is never chosen for these).
std::string SceneKindOf(const physics::BallState& initial, const physics::ModelParameters& p);

struct ModelChoice {
  physics::SimulationOptions options;
  std::string kind;
  double expected_error_m = 0.0;  // the method's p95 error on this kind of scene
  double expected_us = 0.0;       // its median time per shot
  bool accuracy_met = true;       // false: no method is that accurate, the most accurate is used
};

// Throws std::invalid_argument unless accuracy is a positive finite number.
ModelChoice ChooseModel(const physics::BallState& initial, const physics::ModelParameters& p,
                        double accuracy_m);

// A table scene's default accuracy: 5 mm per motion between events, just above the approximate
// 5-DOF model's own p95 error on side-spin motion (4.1 mm against the integral model,
// docs/benchmarks/model_choice.json), so that the approximate model, not the integral one (17
// times slower), moves a spinning ball; the closed form moves the rolling ones.
inline constexpr double kSceneAccuracy = 5e-3;  // [m]

// The 5-DOF method `--model auto` gives what it moves on a table (sliding or spinning balls): the
// cheapest whose error on side-spin motion, the hardest of its kinds, is within `accuracy_m`.
physics::SimulationOptions TableMotionMethod(const physics::ModelParameters& p,
                                             double accuracy_m = kSceneAccuracy);

// `--model auto` on a table (what `billiard simulate --scene` runs by default, and what the pot
// planner checks its plans against): table::FiveDofWhereNeeded with TableMotionMethod. Throws std::invalid_argument unless
// accuracy_m is a positive finite number.
decltype(table::TableSimulationOptions::five_dof) TableMotion(
    const physics::ModelParameters& p, double accuracy_m = kSceneAccuracy);

}  // namespace billiard::model_choice
