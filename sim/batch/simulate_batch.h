// Many independent one-ball simulations at once, on a thread pool (thread_pool.h): what the
// benchmarks' references, shot selection and identification run.
//
// Each shot is physics::Simulate on its own inputs, so result i is, bit for bit, what
// Simulate(params, shots[i].initial, shots[i].t_end, options) returns, whatever the thread count;
// a shot Simulate refuses or fails (a non-finite state, a step budget) carries the reason, and
// the others complete.
#pragma once

#include <vector>

#include "sim/batch/thread_pool.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::batch {

struct BatchShot {
  physics::BallState initial = physics::BallState::Zero();
  double t_end = 0.0;  // [s]
};

// Every shot simulated with `options` on `pool`; result i is shot i's.
std::vector<JobResult<physics::SimulationResult>> SimulateBatch(
    const physics::ModelParameters& params, const std::vector<BatchShot>& shots,
    const physics::SimulationOptions& options, ThreadPool& pool,
    const Progress& progress = nullptr);

// The same on a pool of `threads` threads, started for this batch.
std::vector<JobResult<physics::SimulationResult>> SimulateBatch(
    const physics::ModelParameters& params, const std::vector<BatchShot>& shots,
    const physics::SimulationOptions& options, int threads = DefaultThreadCount());

}  // namespace billiard::batch
