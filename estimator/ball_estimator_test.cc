// The estimator on rendered frames (sim/table_renderer.h) of simulated shots: 1280x720 at
// 120 Hz with sensor noise and motion blur, compared with the ground truth.
#include "ball_estimator.h"

#include <gtest/gtest.h>

#include <chrono>

#include "table_renderer.h"
#include "test_scenes.h"

namespace billiard::estimator {
namespace {

using testing::Errors;
using testing::Pool;

struct EstimatorRun {
  Errors errors;
  double estimate_ms_per_frame = 0.0;
  int full_detects = 0, frames = 0;
};

EstimatorRun EstimateRendered(const testing::Scene& scene, double duration, const CameraModel& camera) {
  RenderOptions render;
  render.noise_sigma = 3.0;
  render.exposure_s = 1.0 / 240;  // half the frame interval: a streak of up to 1.5 cm
  const TableRenderer renderer(camera, Pool(), render);
  std::vector<RenderBall> balls;
  for (std::size_t i = 0; i < scene.rest.size(); ++i) {
    balls.push_back({static_cast<int>(i), PoolBallColour(static_cast<int>(i)),
                     [&scene, i](double t) { return scene.At(i, t); }});
  }
  EstimatorOptions options;
  options.tracker.measurement_sigma = 0.3e-3;
  BallEstimator estimator(camera, Pool(), options);
  EstimatorRun run;
  cv::Mat frame;
  std::chrono::duration<double, std::milli> spent{0};
  for (double t = 0.0; t < duration; t += 1.0 / 120) {
    renderer.Render(balls, t, &frame);
    FrameStats stats;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(estimator.Process(frame, t, &stats));
    spent += std::chrono::steady_clock::now() - start;
    run.full_detects += stats.full_detect;
    ++run.frames;
    run.errors.Add(scene, t, estimator.Balls());
  }
  run.estimate_ms_per_frame = spent.count() / run.frames;
  return run;
}

TEST(BallEstimator, RenderedShotsOfSixteenBallsAreTrackedWithinTheBounds) {
  const CameraModel camera = CameraModel::Overhead(Pool().table, 1280, 720, 2.5, 0.92,
                                                   {-0.05, 0.01, 0.0, 0.0, 0.0});
  for (unsigned seed : {11u, 12u}) {
    const testing::Scene scene = testing::RandomScene(16, 3, seed, 3.0);
    const EstimatorRun run = EstimateRendered(scene, 3.2, camera);
    const Errors& e = run.errors;
    EXPECT_EQ(e.swaps, 0) << seed;
    EXPECT_EQ(e.lost, 0) << seed;
    EXPECT_EQ(e.identity.size(), 16u) << seed;
    EXPECT_LT(e.Rmse(e.position), 0.5e-3) << seed;
    EXPECT_LT(e.Rmse(e.velocity), 10e-3) << seed;
    std::fprintf(stderr,
                 "seed %u: position RMSE %.3f mm, velocity RMSE %.2f mm/s; %.2f ms per frame "
                 "(%d full detections in %d frames)\n",
                 seed, 1e3 * e.Rmse(e.position), 1e3 * e.Rmse(e.velocity),
                 run.estimate_ms_per_frame, run.full_detects, run.frames);
  }
}

TEST(BallEstimator, RefusesEmptyMisSizedAndBackwardFrames) {
  const CameraModel camera = CameraModel::Overhead(Pool().table, 640, 360);
  BallEstimator estimator(camera, Pool());
  const cv::Mat frame = TableRenderer(camera, Pool()).Render({}, 0.0);
  EXPECT_FALSE(estimator.Process(cv::Mat(), 0.0));
  EXPECT_FALSE(estimator.Process(cv::Mat(100, 100, CV_8UC3, cv::Scalar(0, 0, 0)), 0.0));
  EXPECT_TRUE(estimator.Process(frame, 1.0));
  EXPECT_FALSE(estimator.Process(frame, 0.5));
  EXPECT_TRUE(estimator.Balls().empty());
}

}  // namespace
}  // namespace billiard::estimator
