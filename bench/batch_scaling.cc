#include "bench/batch_scaling.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "bench/format.h"
#include "sim/batch/simulate_batch.h"

namespace billiard::bench {

namespace {

// The final states of one batch, and its wall time.
std::vector<physics::BallState> RunBatch(const physics::ModelParameters& p,
                                         const std::vector<batch::BatchShot>& shots,
                                         const physics::SimulationOptions& options,
                                         batch::ThreadPool& pool, double* wall_ms) {
  const auto start = std::chrono::steady_clock::now();
  const auto results = batch::SimulateBatch(p, shots, options, pool);
  *wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
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
                                 int repeats) {
  BatchScaling scaling;
  scaling.shots = static_cast<int>(scenes.size());
  scaling.repeats = repeats;
  scaling.method = physics::ModelName(options.model) + "/" +
                   physics::IntegratorName(options.integrator) + "/tol=" + Sci(options.tolerance);
  std::vector<batch::BatchShot> shots;
  for (const Scene& s : scenes) shots.push_back({s.initial, s.t_end});
  // The thread counts take turns, repeat by repeat, so that a load that comes and goes on the
  // machine falls on all of them alike.
  std::vector<std::unique_ptr<batch::ThreadPool>> pools;
  for (int threads = 1; threads <= std::max(2, max_threads); threads *= 2) {
    pools.push_back(std::make_unique<batch::ThreadPool>(threads));
  }
  std::vector<std::vector<double>> wall_ms(pools.size(), std::vector<double>(repeats));
  scaling.runs.resize(pools.size());
  std::vector<physics::BallState> sequential;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    for (std::size_t k = 0; k < pools.size(); ++k) {
      const std::vector<physics::BallState> finals =
          RunBatch(p, shots, options, *pools[k], &wall_ms[k][repeat]);
      if (sequential.empty()) sequential = finals;
      scaling.runs[k].identical = scaling.runs[k].identical && finals == sequential;
    }
  }
  for (std::size_t k = 0; k < pools.size(); ++k) {
    BatchScalingRun& run = scaling.runs[k];
    run.threads = pools[k]->threads();
    std::vector<double>& ms = wall_ms[k];
    std::nth_element(ms.begin(), ms.begin() + repeats / 2, ms.end());
    run.wall_ms = ms[repeats / 2];
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
     << "the median wall time of " << s.repeats << " batches; the final states of every thread "
     << "count are " << (identical ? "identical, bit for bit, to" : "**not** identical to")
     << " one thread's.\n\n"
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
  return {{"shots", s.shots}, {"repeats", s.repeats}, {"method", s.method}, {"runs", runs}};
}

}  // namespace billiard::bench
