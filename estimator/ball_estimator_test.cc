// The estimator on rendered frames (sim/table_renderer.h) of simulated shots: 1280x720 at
// 120 Hz with sensor noise and motion blur, compared with the ground truth.
#include "ball_estimator.h"

#include <gtest/gtest.h>

#include "estimator_benchmark.h"
#include "speed_error.h"

namespace billiard::estimator {
namespace {

using shots::Errors;
using shots::Pool;

TEST(BallEstimator, RenderedShotsOfSixteenBallsAreTrackedWithinTheBounds) {
  const CameraModel camera = bench::BenchmarkCamera(Pool());
  for (unsigned seed : {11u, 12u}) {
    const shots::Scene scene = shots::RandomScene(16, 3, seed, 3.0);
    const bench::RenderedRun run = bench::EstimateRenderedScene(
        scene, 3.2, camera, Pool(), bench::BenchmarkRenderOptions());
    const Errors& e = run.errors;
    EXPECT_EQ(e.swaps, 0) << seed;
    EXPECT_EQ(e.lost, 0) << seed;
    EXPECT_EQ(e.identity.size(), 16u) << seed;
    EXPECT_LT(shots::Rmse(e.position), 0.5e-3) << seed;
    EXPECT_LT(shots::Rmse(e.velocity), 10e-3) << seed;
    EXPECT_LT(shots::Rmse(e.moving_velocity), 10e-3) << seed;
    std::fprintf(stderr,
                 "seed %u: position RMSE %.3f mm, velocity RMSE %.2f mm/s (moving %.2f); %.2f ms "
                 "per frame (median; %d full detections in %d frames)\n",
                 seed, 1e3 * shots::Rmse(e.position), 1e3 * shots::Rmse(e.velocity),
                 1e3 * shots::Rmse(e.moving_velocity), bench::Quantile(run.frame_ms, 0.5),
                 run.full_detects, static_cast<int>(run.frame_ms.size()));
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
