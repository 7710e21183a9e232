// The estimator's benchmark: seeded shots (estimator/testing/shot_scenes.h) rendered at
// 1280x720 and 120 Hz with sensor noise and motion blur (sim/render/table_renderer.h), estimated
// frame by frame, and compared with the ground truth; detection plus tracking timed on one core.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "estimator/testing/shot_scenes.h"
#include "sim/camera/camera_model.h"
#include "sim/render/table_renderer.h"

namespace billiard::bench {

struct RenderedRun {
  estimator::shots::Errors errors;
  std::vector<double> frame_ms;  // BallEstimator::Process per frame
  int full_detects = 0;
};

// Renders `scene` every 1 / rate seconds up to `duration` and runs the estimator on each frame.
RenderedRun EstimateRenderedScene(const estimator::shots::Scene& scene, double duration,
                                  const camera::CameraModel& camera,
                                  const physics::ModelParameters& params,
                                  const render::RenderOptions& render, double rate = 120.0);

// The overhead camera of the table simulator at 1280x720, with a mild barrel lens.
camera::CameraModel BenchmarkCamera(const physics::ModelParameters& p);

// The frames the benchmark and the estimator's test render: noise sigma 3 gray levels, an
// exposure of half the frame interval.
render::RenderOptions BenchmarkRenderOptions();

struct EstimatorBenchmarkOptions {
  int scenes = 6;
  int balls = 16;
  int struck = 3;
  double duration = 3.0;  // [s] of each scene
  std::uint32_t seed = 2026;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct EstimatorBenchmarkResult {
  std::string params;
  EstimatorBenchmarkOptions options;
  std::vector<RenderedRun> runs;
  double wall_s = 0.0;
};

EstimatorBenchmarkResult RunEstimatorBenchmark(const physics::ModelParameters& p,
                                               const EstimatorBenchmarkOptions& options);

// Writes estimator_report.md into `dir` (created if missing).
void WriteEstimatorReport(const EstimatorBenchmarkResult& result, const std::string& dir);

nlohmann::json EstimatorSummaryJson(const EstimatorBenchmarkResult& result);

}  // namespace billiard::bench
