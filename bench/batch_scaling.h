// How the batch interface (sim/batch/) scales with cores: the same seeded shots simulated as one
// batch on 1 thread and on 2, 4, ... up to a limit, timed by the wall clock with the thread
// counts interleaved (timing.h), and the results of every thread count compared bit for bit with
// those of one thread.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/scene_suite.h"
#include "bench/timing.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::bench {

struct BatchScalingRun {
  int threads = 1;
  double wall_ms = 0.0;      // one batch (MedianWallUsInterleaved)
  double shots_per_s = 0.0;  // shots / wall time
  double speedup = 1.0;      // over one thread
  bool identical = true;     // every final state equal, bit for bit, to one thread's
};

struct BatchScaling {
  int shots = 0;
  TimingBudget timing;
  std::string method;  // the simulation's model, integrator and tolerance
  std::vector<BatchScalingRun> runs;
};

// Simulates `scenes` as one batch with `options` on each thread count of 1, 2, 4, ... up to
// max_threads (at least 2), timed with `timing`. Throws std::runtime_error when a shot fails.
BatchScaling MeasureBatchScaling(const physics::ModelParameters& p,
                                 const std::vector<Scene>& scenes,
                                 const physics::SimulationOptions& options, int max_threads,
                                 const TimingBudget& timing);

// The report's section: a sentence and a table.
std::string BatchScalingMarkdown(const BatchScaling& scaling);
nlohmann::json BatchScalingJson(const BatchScaling& scaling);

}  // namespace billiard::bench
