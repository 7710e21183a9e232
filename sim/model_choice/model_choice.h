// `--model auto`: the cheapest model and integrator whose measured error on this kind of scene
// stays within the requested accuracy.
//
// The table is docs/benchmarks/model_choice.json, written by `billiard bench` and compiled into
// the library: per scene kind, every benchmarked method's median time per 8 s shot and its p95
// endpoint distance from the integral model converged (the most faithful model here).
//
// Module: billiard::model_choice. Includes the physics (sim/physics/) and nothing else of the
// project.
#pragma once

#include <string>

#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

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

}  // namespace billiard::model_choice
