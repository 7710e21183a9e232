#include "bench/shot_fit_benchmark.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "estimator/ball_estimator.h"
#include "sim/camera/camera_model.h"
#include "sim/render/table_renderer.h"
#include "sim/shot_fit/shot_recorder.h"

namespace billiard::bench {

namespace {

// The colours of a carom set from pool's numbers: white (0), yellow (1) and red (3).
constexpr int kColours[] = {0, 1, 3};

std::int64_t Utime(double t) { return std::llround(t * 1e6); }

std::optional<shot_fit::TrackedShot> CameraTrackedShot(const table::TableGeometry& table,
                                                       const physics::ModelParameters& truth,
                                                       const shot_fit::SyntheticScene& scene,
                                                       const CameraShotOptions& options,
                                                       std::uint64_t seed) {
  // The simulation on the shot's own clock, struck at its time 0: a shot of the scene's balls
  // at rest, as long as the camera watches.
  shot_fit::TrackedShot still;
  for (const Eigen::Vector2d& start : scene.starts)
    still.balls.push_back({"", {0.0, options.duration}, {start, start}});
  shot_fit::Strike strike = scene.strike;
  strike.time = 0.0;
  const table::TableSimulation sim = shot_fit::SimulateShot(table, truth, still, strike);
  // The impact between two frames, where the scene puts it within a frame period.
  const double period = 1.0 / options.rate;
  const double impact = options.settle + std::fmod(scene.strike.time, period);

  const camera::CameraModel camera =
      camera::CameraModel::Overhead(truth.table, options.width, options.height);
  render::RenderOptions look;
  look.seed = seed;
  const render::TableRenderer renderer(camera, truth, look);
  estimator::BallEstimator estimator(camera, truth);
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < scene.starts.size(); ++i) {
    const Eigen::Vector2d start = scene.starts[i];
    balls.push_back({kColours[i % 3], render::PoolBallColour(kColours[i % 3]),
                     [&sim, i, impact, start](double t) -> Eigen::Vector2d {
                       if (t < impact) return start;
                       return sim.StateAt(i, std::min(t - impact, sim.time())).head<2>();
                     }});
  }
  shot_fit::ShotRecorder recorder(options.duration + options.settle + 1.0, options.thinning);
  bool struck = false;
  cv::Mat frame;
  const int frames = static_cast<int>(std::ceil((impact + options.duration) / period));
  for (int k = 0; k <= frames; ++k) {
    const double t = k * period;
    if (!struck && t > impact) {
      // The cue strikes the track the estimator sees nearest the cue ball.
      std::optional<int> cue;
      double nearest = std::numeric_limits<double>::infinity();
      for (const estimator::TrackedBall& b : estimator.Balls()) {
        const double d = (b.position() - scene.starts[0]).norm();
        if (d < nearest) nearest = d, cue = b.id;
      }
      if (!cue) return std::nullopt;
      recorder.Strike(Utime(impact), *cue);
      struck = true;
    }
    renderer.Render(balls, t, &frame);
    estimator.Process(frame, t);
    std::vector<shot_fit::TrackSample> tracks;
    for (const estimator::TrackedBall& b : estimator.Balls()) tracks.push_back({b.id, b.position()});
    recorder.State(Utime(t), tracks);
  }
  recorder.Finish();
  if (recorder.shots().empty()) return std::nullopt;
  return recorder.shots().front();
}

}  // namespace

std::vector<std::optional<shot_fit::TrackedShot>> CameraTrackedShots(
    const table::TableGeometry& table, const physics::ModelParameters& truth,
    const std::vector<shot_fit::SyntheticScene>& scenes, const CameraShotOptions& options,
    batch::ThreadPool& pool) {
  auto jobs = pool.Map(scenes.size(), [&](std::size_t k) {
    std::optional<shot_fit::TrackedShot> shot =
        CameraTrackedShot(table, truth, scenes[k], options, k + 1);
    if (shot) shot->id = std::to_string(k + 1);
    return shot;
  });
  std::vector<std::optional<shot_fit::TrackedShot>> shots;
  for (auto& job : jobs) {
    if (!job.ok()) throw std::runtime_error("a camera-tracked shot failed: " + job.error);
    shots.push_back(std::move(*job.value));
  }
  return shots;
}

}  // namespace billiard::bench
