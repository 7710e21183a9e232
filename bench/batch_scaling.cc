#include "bench/batch_scaling.h"

#include <algorithm>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "bench/format.h"
#include "sim/batch/simulate_batch.h"

namespace billiard::bench {

namespace {

// The final states of one batch.
std::vector<physics::BallState> FinalStates(const physics::ModelParameters& p,
                                            const std::vector<batch::BatchShot>& shots,
                                            const physics::SimulationOptions& options,
                                            batch::ThreadPool& pool) {
  const auto results = batch::SimulateBatch(p, shots, options, pool);
  std::vector<physics::BallState> finals;
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (!results[i].ok()) {
      throw std::runtime_error("batch scaling: shot " + std::to_string(i) +
                               " failed: " + results[i].error);
    }
    finals.push_back(results[i].value->final_state);
  }
  return finals;
}

}  // namespace

BatchScaling MeasureBatchScaling(const physics::ModelParameters& p,
                                 const std::vector<Scene>& scenes,
                                 const physics::SimulationOptions& options, int max_threads,
                                 const TimingBudget& timing) {
  BatchScaling scaling;
  scaling.shots = static_cast<int>(scenes.size());
  scaling.timing = timing;
  scaling.method = physics::ModelName(options.model) + "/" +
                   physics::IntegratorName(options.integrator) + "/tol=" + Sci(options.tolerance);
  std::vector<batch::BatchShot> shots;
  for (const Scene& s : scenes) shots.push_back({s.initial, s.t_end});
  std::vector<std::unique_ptr<batch::ThreadPool>> pools;
  for (int threads = 1; threads <= std::max(2, max_threads); threads *= 2) {
    pools.push_back(std::make_unique<batch::ThreadPool>(threads));
  }
  scaling.runs.resize(pools.size());
  std::vector<physics::BallState> sequential;  // one thread's, which runs first
  std::vector<std::function<void()>> runs;
  for (std::size_t k = 0; k < pools.size(); ++k) {
    runs.push_back([&, k] {
      const std::vector<physics::BallState> finals = FinalStates(p, shots, options, *pools[k]);
      if (sequential.empty()) sequential = finals;
      scaling.runs[k].identical = scaling.runs[k].identical && finals == sequential;
    });
  }
  const std::vector<double> wall_us = MedianWallUsInterleaved(runs, timing);
  for (std::size_t k = 0; k < pools.size(); ++k) {
    BatchScalingRun& run = scaling.runs[k];
    run.threads = pools[k]->threads();
    run.wall_ms = wall_us[k] * 1e-3;
    run.shots_per_s = scaling.shots / (run.wall_ms * 1e-3);
    run.speedup = scaling.runs.front().wall_ms / run.wall_ms;
  }
  return scaling;
}

std::string BatchScalingMarkdown(const BatchScaling& s) {
  const bool identical = std::all_of(s.runs.begin(), s.runs.end(),
                                     [](const BatchScalingRun& r) { return r.identical; });
  std::ostringstream md;
  md << "The same " << s.shots << " seeded random shots (" << s.method
     << ", 8 s each) simulated as one batch (`sim/batch/simulate_batch.h`) on each thread count, "
     << "the thread counts interleaved (the median of " << s.timing.batches
     << " samples each); the final states of every thread count are "
     << (identical ? "identical, bit for bit, to" : "**not** identical to") << " one thread's.\n\n"
     << "| threads | batch wall ms | shots per second | speedup |\n|---|---|---|---|\n";
  for (const BatchScalingRun& r : s.runs) {
    md << "| " << r.threads << " | " << Fixed(r.wall_ms, 2) << " | " << Fixed(r.shots_per_s, 0)
       << " | " << Fixed(r.speedup, 2) << " |\n";
  }
  return md.str();
}

nlohmann::json BatchScalingJson(const BatchScaling& s) {
  nlohmann::json runs = nlohmann::json::array();
  for (const BatchScalingRun& r : s.runs) {
    runs.push_back({{"threads", r.threads},
                    {"wall_ms", r.wall_ms},
                    {"shots_per_s", r.shots_per_s},
                    {"speedup", r.speedup},
                    {"identical", r.identical}});
  }
  return {{"shots", s.shots}, {"samples", s.timing.batches}, {"method", s.method}, {"runs", runs}};
}

}  // namespace billiard::bench
