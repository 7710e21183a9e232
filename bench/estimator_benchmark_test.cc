// The estimator on rendered frames (sim/render/table_renderer.h) of simulated shots: 1280x720 at
// 120 Hz with sensor noise and motion blur, compared with the ground truth: the acceptance
// bounds of the synthetic benchmark (bench-estimator) on two seeds.
#include "bench/estimator_benchmark.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "bench/speed_error.h"

namespace billiard::bench {
namespace {

using estimator::shots::Errors;
using estimator::shots::Pool;
using estimator::shots::Rmse;

TEST(EstimatorBenchmark, RenderedShotsOfSixteenBallsAreTrackedWithinTheBounds) {
  const camera::CameraModel camera = BenchmarkCamera(Pool());
  for (unsigned seed : {11u, 12u}) {
    const estimator::shots::Scene scene = estimator::shots::RandomScene(16, 3, seed, 3.0);
    const RenderedRun run =
        EstimateRenderedScene(scene, 3.2, camera, Pool(), BenchmarkRenderOptions());
    const Errors& e = run.errors;
    EXPECT_EQ(e.swaps, 0) << seed;
    EXPECT_EQ(e.lost, 0) << seed;
    EXPECT_EQ(e.identity.size(), 16u) << seed;
    EXPECT_LT(Rmse(e.position), 0.5e-3) << seed;
    EXPECT_LT(Rmse(e.velocity), 10e-3) << seed;
    EXPECT_LT(Rmse(e.moving_velocity), 10e-3) << seed;
    std::fprintf(stderr,
                 "seed %u: position RMSE %.3f mm, velocity RMSE %.2f mm/s (moving %.2f); %.2f ms "
                 "per frame (median; %d full detections in %d frames)\n",
                 seed, 1e3 * Rmse(e.position), 1e3 * Rmse(e.velocity),
                 1e3 * Rmse(e.moving_velocity), Quantile(run.frame_ms, 0.5), run.full_detects,
                 static_cast<int>(run.frame_ms.size()));
  }
}

}  // namespace
}  // namespace billiard::bench
