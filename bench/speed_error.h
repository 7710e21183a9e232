// The speed-against-error benchmark: every method on every scene, timed on one core, its endpoint
// compared with the same model converged and with the integral model converged; and our default
// method against the peers and the floor on Figs. 6-10 (peer_comparison.h).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "bench/batch_scaling.h"
#include "bench/peer_comparison.h"
#include "bench/scene_suite.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"

namespace billiard::bench {

// A model with its integrator and tolerances.
struct Method {
  physics::Model model = physics::Model::kApproximate;
  physics::Integrator integrator = physics::Integrator::kRodas4;
  double tolerance = 1e-7;
  double quadrature_tolerance = 1e-6;  // integral model only

  std::string Family() const;  // "closed-form", "approx/rodas4", "integral/rodas4", ...
  std::string Name() const;    // Family() plus the tolerances
  physics::SimulationOptions Options() const;
};

// The methods of a full run, or of a quick one.
std::vector<Method> BenchmarkMethods(bool quick);

// One method on one scene.
struct MethodRun {
  std::string method, scene, group;
  std::string kind;  // SceneKindOf (model_choice.h)
  bool ok = true;
  std::string failure;   // why the run failed, when !ok
  double wall_us = 0.0;  // MedianWallUs (timing.h): cheap runs repeated, median of batch means
  long steps = 0, rhs_evals = 0;
  double error_self_m = 0.0;      // endpoint distance from the same model converged
  double error_integral_m = 0.0;  // endpoint distance from the integral model converged
};

// "all" and the scene kinds that the model choice distinguishes (SceneKindOf).
inline const std::vector<std::string> kSceneKinds = {"all", "rolling", "sliding", "side-spin"};

struct MethodSummary {
  Method method;
  std::string kind;  // one of kSceneKinds
  int runs = 0, failures = 0;
  double median_us = 0, p95_us = 0, median_steps = 0, median_rhs_evals = 0;
  double median_error_self_m = 0, p95_error_self_m = 0, max_error_self_m = 0;
  double median_error_integral_m = 0, p95_error_integral_m = 0, max_error_integral_m = 0;
};

struct BenchmarkOptions {
  bool quick = false;
  int random_shots = 200;
  std::uint32_t seed = 2026;
  // Threads for the references, and the most the batch scaling measures; every other timed run
  // is on one thread.
  int threads = 2;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct BenchmarkResult {
  std::string params;
  std::vector<Scene> scenes;
  std::vector<Method> methods;
  Method approx_reference, integral_reference;
  double integral_reference_quadrature_error = 0.0;
  std::vector<MethodRun> runs;
  std::vector<MethodSummary> summaries;
  PeerComparison peers;        // on the "figure" scenes
  BatchScaling batch_scaling;  // the random shots as one batch on 1, 2, ... threads
  double wall_s = 0.0;
};

BenchmarkResult RunBenchmark(const physics::ModelParameters& p, const BenchmarkOptions& options);

// The q-quantile (0..1, linear interpolation) of `values`; 0 when empty.
double Quantile(std::vector<double> values, double q);

}  // namespace billiard::bench
