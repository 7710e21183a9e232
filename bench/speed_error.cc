#include "bench/speed_error.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "bench/timing.h"
#include "sim/batch/simulate_batch.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {

namespace {

// The references report their progress every this many scenes.
constexpr std::size_t kReferenceProgressEvery = 10;

// The batch scaling's timing: 15 samples of each thread count, about 0.5 s of each (200 shots
// take about 25 ms on one core).
constexpr TimingBudget kBatchScalingTiming{500000.0, 15};

std::string Scientific(double x) {
  char text[16];
  std::snprintf(text, sizeof text, "%.0e", x);
  return text;
}

double EndpointDistance(const physics::BallState& a, const physics::BallState& b) {
  return (a.head<2>() - b.head<2>()).norm();
}

// Final states of `method` on every scene, simulated as one batch on `pool`.
std::vector<physics::BallState> Converged(const physics::ModelParameters& p,
                                          const std::vector<Scene>& scenes, const Method& method,
                                          batch::ThreadPool& pool, const BenchmarkOptions& options,
                                          double* quadrature_error) {
  std::vector<batch::BatchShot> shots;
  for (const Scene& s : scenes) shots.push_back({s.initial, s.t_end});
  const auto results = batch::SimulateBatch(
      p, shots, method.Options(), pool, [&](std::size_t done, std::size_t total) {
        if (done % kReferenceProgressEvery == 0 || done == total) {
          options.progress("reference " + method.Name() + ": " + std::to_string(done) + "/" +
                           std::to_string(total) + " scenes");
        }
      });
  std::vector<physics::BallState> finals;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    if (!results[i].ok()) {
      throw std::runtime_error("reference " + method.Name() + " failed on " + scenes[i].name +
                               ": " + results[i].error);
    }
    const physics::SimulationResult& r = *results[i].value;
    finals.push_back(r.final_state);
    if (r.quadrature && quadrature_error) *quadrature_error = r.quadrature->error_estimate;
  }
  return finals;
}

// Timed on the calling thread (MedianWallUs: cheap methods repeated for about 2 ms, the median
// of the batch means); *result holds the last run.
MethodRun TimeRun(const physics::ModelParameters& p, const Scene& scene, const Method& method,
                  physics::SimulationResult* result) {
  MethodRun run;
  run.method = method.Name();
  run.scene = scene.name;
  run.group = scene.group;
  run.kind = model_choice::SceneKindOf(scene.initial, p);
  const physics::SimulationOptions options = method.Options();
  try {
    run.wall_us =
        MedianWallUs([&] { *result = physics::Simulate(p, scene.initial, scene.t_end, options); });
    run.steps = result->stats.steps;
    run.rhs_evals = result->stats.rhs_evals;
  } catch (const std::exception& e) {
    run.ok = false;
    run.failure = e.what();
  }
  return run;
}

MethodSummary Summarize(const Method& method, const std::string& kind,
                        const std::vector<MethodRun>& runs) {
  MethodSummary s;
  s.method = method;
  s.kind = kind;
  std::vector<double> us, steps, rhs, self, integral;
  for (const MethodRun& r : runs) {
    if (r.method != method.Name()) continue;
    if (kind != "all" && kind != r.kind) continue;
    ++s.runs;
    if (!r.ok) {
      ++s.failures;
      continue;
    }
    us.push_back(r.wall_us);
    steps.push_back(r.steps);
    rhs.push_back(r.rhs_evals);
    self.push_back(r.error_self_m);
    integral.push_back(r.error_integral_m);
  }
  s.median_us = Quantile(us, 0.5);
  s.p95_us = Quantile(us, 0.95);
  s.median_steps = Quantile(steps, 0.5);
  s.median_rhs_evals = Quantile(rhs, 0.5);
  s.median_error_self_m = Quantile(self, 0.5);
  s.p95_error_self_m = Quantile(self, 0.95);
  s.max_error_self_m = Quantile(self, 1.0);
  s.median_error_integral_m = Quantile(integral, 0.5);
  s.p95_error_integral_m = Quantile(integral, 0.95);
  s.max_error_integral_m = Quantile(integral, 1.0);
  return s;
}

}  // namespace

std::string Method::Family() const {
  if (model == physics::Model::kClosedForm) return physics::ModelName(model);
  return physics::ModelName(model) + "/" + physics::IntegratorName(integrator);
}

std::string Method::Name() const {
  if (model == physics::Model::kClosedForm) return Family();
  std::string name = Family() + "/tol=" + Scientific(tolerance);
  if (model == physics::Model::kIntegral) name += "/quad=" + Scientific(quadrature_tolerance);
  return name;
}

physics::SimulationOptions Method::Options() const {
  physics::SimulationOptions o;
  o.model = model;
  o.integrator = integrator;
  o.tolerance = tolerance;
  o.quadrature_tolerance = quadrature_tolerance;
  // An explicit method on the stiff phases: give up rather than run for minutes.
  if (integrator == physics::Integrator::kDopri5) o.max_steps = 3'000'000;
  return o;
}

std::vector<Method> BenchmarkMethods(bool quick) {
  using M = physics::Model;
  using I = physics::Integrator;
  std::vector<Method> methods = {{M::kClosedForm, I::kRodas4, 0.0, 0.0}};
  const std::vector<double> rodas =
      quick ? std::vector<double>{1e-5, 1e-7} : std::vector<double>{1e-4, 1e-5, 1e-6, 1e-7, 1e-8};
  for (double tol : rodas) methods.push_back({M::kApproximate, I::kRodas4, tol, 0.0});
  const std::vector<double> dopri =
      quick ? std::vector<double>{1e-6} : std::vector<double>{1e-5, 1e-7};
  for (double tol : dopri) methods.push_back({M::kApproximate, I::kDopri5, tol, 0.0});
  methods.push_back({M::kIntegral, I::kRodas4, 1e-5, 1e-3});
  if (!quick) methods.push_back({M::kIntegral, I::kRodas4, 1e-7, 1e-6});
  return methods;
}

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double position = q * (values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(position);
  if (below + 1 >= values.size()) return values.back();
  const double f = position - below;
  return values[below] * (1 - f) + values[below + 1] * f;
}

BenchmarkResult RunBenchmark(const physics::ModelParameters& p, const BenchmarkOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  BenchmarkResult result;
  result.params = params::ParameterSetLabel(p);
  result.scenes = SceneSuite(p, options.random_shots, options.seed);
  result.methods = BenchmarkMethods(options.quick);
  result.approx_reference = {physics::Model::kApproximate, physics::Integrator::kRodas4, 1e-10,
                             0.0};
  result.integral_reference = {physics::Model::kIntegral, physics::Integrator::kRodas4,
                               options.quick ? 1e-8 : 1e-9, 1e-6};
  batch::ThreadPool pool(options.threads);
  const std::vector<physics::BallState> approx_ref =
      Converged(p, result.scenes, result.approx_reference, pool, options, nullptr);
  const std::vector<physics::BallState> integral_ref =
      Converged(p, result.scenes, result.integral_reference, pool, options,
                &result.integral_reference_quadrature_error);

  for (const Method& method : result.methods) {
    options.progress("timing " + method.Name() + " on " + std::to_string(result.scenes.size()) +
                     " scenes");
    for (std::size_t i = 0; i < result.scenes.size(); ++i) {
      physics::SimulationResult sim;
      MethodRun run = TimeRun(p, result.scenes[i], method, &sim);
      if (run.ok) {
        const physics::BallState& self =
            method.model == physics::Model::kIntegral ? integral_ref[i] : approx_ref[i];
        run.error_self_m = method.model == physics::Model::kClosedForm
                               ? 0.0
                               : EndpointDistance(sim.final_state, self);
        run.error_integral_m = EndpointDistance(sim.final_state, integral_ref[i]);
      }
      result.runs.push_back(run);
    }
  }
  const std::vector<Scene> random_shots = ScenesOfGroup(result.scenes, "random");
  options.progress("batch scaling on " + std::to_string(random_shots.size()) + " shots");
  result.batch_scaling =
      MeasureBatchScaling(p, random_shots, {}, options.threads, kBatchScalingTiming);
  for (const Method& method : result.methods) {
    for (const std::string& kind : kSceneKinds) {
      result.summaries.push_back(Summarize(method, kind, result.runs));
    }
  }
  result.peers = ComparePeers(p, ScenesOfGroup(result.scenes, "figure"), options.progress);
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace billiard::bench
