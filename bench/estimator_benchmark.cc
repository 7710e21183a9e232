#include "bench/estimator_benchmark.h"

#include <chrono>
#include <filesystem>

#include "bench/format.h"
#include "bench/speed_error.h"
#include "estimator/ball_estimator.h"
#include "sim/params/parameter_sets.h"

namespace billiard::bench {

namespace {

struct Totals {
  std::vector<double> position, velocity, moving_velocity, frame_ms;
  int swaps = 0, lost = 0, frames = 0, full_detects = 0;
};

Totals Total(const EstimatorBenchmarkResult& r) {
  Totals t;
  for (const RenderedRun& run : r.runs) {
    const auto& e = run.errors;
    t.position.insert(t.position.end(), e.position.begin(), e.position.end());
    t.velocity.insert(t.velocity.end(), e.velocity.begin(), e.velocity.end());
    t.moving_velocity.insert(t.moving_velocity.end(), e.moving_velocity.begin(),
                             e.moving_velocity.end());
    t.frame_ms.insert(t.frame_ms.end(), run.frame_ms.begin(), run.frame_ms.end());
    t.swaps += e.swaps;
    t.lost += e.lost;
    t.frames += static_cast<int>(run.frame_ms.size());
    t.full_detects += run.full_detects;
  }
  return t;
}

using estimator::shots::Rmse;

}  // namespace

camera::CameraModel BenchmarkCamera(const physics::ModelParameters& p) {
  return camera::CameraModel::Overhead(p.table, 1280, 720, 2.5, 0.92, {-0.05, 0.01, 0.0, 0.0, 0.0});
}

render::RenderOptions BenchmarkRenderOptions() {
  render::RenderOptions render;
  render.noise_sigma = 3.0;
  render.exposure_s = 1.0 / 240;
  return render;
}

RenderedRun EstimateRenderedScene(const estimator::shots::Scene& scene, double duration,
                                  const camera::CameraModel& camera,
                                  const physics::ModelParameters& params,
                                  const render::RenderOptions& render, double rate) {
  const render::TableRenderer renderer(camera, params, render);
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < scene.rest.size(); ++i) {
    const int id = static_cast<int>(i);
    balls.push_back({id, render::PoolBallColour(id % 16),
                     [&scene, i](double t) { return scene.At(i, t); },
                     render::PoolBallStriped(id % 16)});
  }
  estimator::EstimatorOptions options;
  options.tracker.measurement_sigma = 0.3e-3;
  estimator::BallEstimator estimator(camera, params, options);
  RenderedRun run;
  cv::Mat frame;
  const int frames = static_cast<int>(duration * rate);
  for (int f = 0; f < frames; ++f) {
    const double t = f / rate;
    renderer.Render(balls, t, &frame);
    estimator::FrameStats stats;
    const auto start = std::chrono::steady_clock::now();
    estimator.Process(frame, t, &stats);
    run.frame_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    run.full_detects += stats.full_detect;
    run.errors.Add(scene, t, estimator.Balls());
  }
  return run;
}

EstimatorBenchmarkResult RunEstimatorBenchmark(const physics::ModelParameters& p,
                                               const EstimatorBenchmarkOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  EstimatorBenchmarkResult r;
  r.params = params::ParameterSetLabel(p);
  r.options = options;
  for (int i = 0; i < options.scenes; ++i) {
    const auto scene = estimator::shots::RandomScene(options.balls, options.struck,
                                                     options.seed + i, options.duration);
    r.runs.push_back(EstimateRenderedScene(scene, options.duration + 0.2, BenchmarkCamera(p), p,
                                           BenchmarkRenderOptions()));
    options.progress("scene " + std::to_string(i + 1) + "/" + std::to_string(options.scenes));
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

void WriteEstimatorReport(const EstimatorBenchmarkResult& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const Totals t = Total(r);
  double mean_ms = 0.0;
  for (double ms : t.frame_ms) mean_ms += ms / t.frame_ms.size();
  std::ofstream md = OpenForWriting(dir + "/estimator_report.md");
  md << "# Estimator benchmark\n\n"
     << r.options.scenes << " seeded scenes (seed " << r.options.seed << ", "
     << "`estimator/testing/shot_scenes.h`) on the " << r.params
     << " parameter set: " << r.options.balls << " balls, " << r.options.struck
     << " struck at 0.5-3 m/s with draw to follow and side spin, simulated with the "
     << "5-DOF model for " << r.options.duration << " s. Frames rendered at 1280x720 and 120 Hz "
     << "(`sim/render/table_renderer.h`: noise sigma 3 gray levels, "
     << "motion blur over half the frame interval, a mild barrel lens), then detected and "
     << "tracked (`estimator/ball_estimator.h`). Errors count from 0.1 s on; velocity errors "
     << "not within 0.3 s after a strike, the end of sliding or a stop. Times are "
     << "`BallEstimator::Process` on one core of this 2-core machine. Produced by `billiard "
     << "bench-estimator`.\n\n"
     << "| measure | value | target |\n|---|---|---|\n"
     << "| position RMSE | " << Fixed(1e3 * Rmse(t.position), 3) << " mm | < 0.5 mm |\n"
     << "| position p95 / max error | " << Fixed(1e3 * Quantile(t.position, 0.95), 3) << " / "
     << Fixed(1e3 * Quantile(t.position, 1.0), 3) << " mm | |\n"
     << "| velocity RMSE (converged) | " << Fixed(1e3 * Rmse(t.velocity), 2)
     << " mm/s | < 10 mm/s |\n"
     << "| velocity RMSE of the moving balls (converged) | "
     << Fixed(1e3 * Rmse(t.moving_velocity), 2) << " mm/s | |\n"
     << "| swapped / lost ball-frames | " << t.swaps << " / " << t.lost << " | 0 / 0 |\n"
     << "| detection + tracking per frame, mean / median / p95 | " << Fixed(mean_ms, 2) << " / "
     << Fixed(Quantile(t.frame_ms, 0.5), 2) << " / " << Fixed(Quantile(t.frame_ms, 0.95), 2)
     << " ms | |\n"
     << "| frames per second per core (from the mean) | " << Fixed(1e3 / mean_ms, 0)
     << " | >= 300 |\n"
     << "| full-frame detections | " << t.full_detects << " of " << t.frames << " frames | |\n";
  if (!md) throw std::runtime_error("writing the estimator report failed");
}

nlohmann::json EstimatorSummaryJson(const EstimatorBenchmarkResult& r) {
  const Totals t = Total(r);
  return {{"params", r.params},
          {"scenes", r.options.scenes},
          {"frames", t.frames},
          {"position_rmse_m", Rmse(t.position)},
          {"velocity_rmse_m_s", Rmse(t.velocity)},
          {"moving_velocity_rmse_m_s", Rmse(t.moving_velocity)},
          {"swaps", t.swaps},
          {"lost", t.lost},
          {"median_frame_ms", Quantile(t.frame_ms, 0.5)},
          {"p95_frame_ms", Quantile(t.frame_ms, 0.95)},
          {"wall_s", r.wall_s}};
}

}  // namespace billiard::bench
