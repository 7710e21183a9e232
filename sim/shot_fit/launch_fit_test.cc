#include "sim/shot_fit/launch_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

// The loop's camera: 30 frames a second, half a millimetre of error per coordinate.
constexpr double kPeriod = 1.0 / 30.0, kNoise = 5e-4, kDuration = 0.6;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

table::TableGeometry PoolTable() {
  return table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
}

TrackedShot Tracked(const SyntheticScene& scene, double noise, std::uint64_t seed) {
  return SimulateTrackedShot(PoolTable(), Pool(), scene.starts, 0, scene.strike, kDuration,
                             kPeriod, noise, 0.0, seed);
}

Eigen::Vector2d TrueLaunch(const SyntheticScene& scene) {
  return physics::StrikeBall(scene.strike.stroke, scene.starts[0], Pool())
      .segment<2>(physics::kVx);
}

// Untracked (no noise), the fit's model is the simulation's: the launch comes back exactly, the
// strike time with it, whatever spin the tip gave.
TEST(FitLaunch, RecoversTheLaunchOfANoiselessTrack) {
  int fitted = 0;
  for (const SyntheticScene& scene : SyntheticScenes(PoolTable(), Pool().ball.radius, 20, 3)) {
    const MeasuredLaunch launch = FitLaunch(Tracked(scene, 0.0, 1), scene.strike.stroke, Pool());
    if (!launch.ok) continue;
    ++fitted;
    EXPECT_LT((launch.velocity - TrueLaunch(scene)).norm(), 1e-5) << launch.samples;
    EXPECT_NEAR(launch.strike_time, scene.strike.time, 1e-5);
    EXPECT_LT(launch.rms, 1e-6);
  }
  EXPECT_GE(fitted, 10);
}

// With the tracking's noise, the launch's error is what its covariance says: the squared
// Mahalanobis errors average 2 (chi-square with two degrees of freedom) over many shots.
TEST(FitLaunch, ItsCovarianceIsTheErrorsSpread) {
  double sum = 0.0;
  int fitted = 0;
  std::uint64_t seed = 10;
  for (const SyntheticScene& scene : SyntheticScenes(PoolTable(), Pool().ball.radius, 300, 4)) {
    const MeasuredLaunch launch =
        FitLaunch(Tracked(scene, kNoise, ++seed), scene.strike.stroke, Pool());
    if (!launch.ok) continue;
    ++fitted;
    const Eigen::Vector2d e = launch.velocity - TrueLaunch(scene);
    sum += e.dot(launch.covariance.ldlt().solve(e));
  }
  ASSERT_GE(fitted, 150);
  EXPECT_NEAR(sum / fitted, 2.0, 0.5);
}

// The samples end before the cue ball reaches another ball: a ball 40 cm ahead leaves the frames
// of those 40 cm less the margin for a faster stroke (at 2.6 m/s, four frames at most), one touching
// leaves none.
TEST(FitLaunch, StopsBeforeTheFirstCollision) {
  SyntheticScene scene;
  scene.strike.stroke.speed = 2.0;
  scene.strike.time = 0.01;
  const double r = Pool().ball.radius;
  scene.starts = {{1.0, 0.6}, {1.0 + 2 * r + 0.4, 0.6}};
  const MeasuredLaunch near = FitLaunch(Tracked(scene, 0.0, 1), scene.strike.stroke, Pool());
  ASSERT_TRUE(near.ok) << near.reason;
  EXPECT_LE(near.samples, 4);
  EXPECT_LT((near.velocity - TrueLaunch(scene)).norm(), 1e-5);

  scene.starts[1] = {1.0 + 2 * r + 0.001, 0.6};
  const MeasuredLaunch touching = FitLaunch(Tracked(scene, 0.0, 1), scene.strike.stroke, Pool());
  EXPECT_FALSE(touching.ok);
  EXPECT_NE(touching.reason.find("before it met"), std::string::npos) << touching.reason;
}

// A ball that never moves has no launch.
TEST(FitLaunch, RefusesABallThatNeverMoves) {
  TrackedShot shot;
  shot.balls = {{"1", {0.0, 0.1, 0.2}, {{1.0, 0.6}, {1.0, 0.6}, {1.0, 0.6}}}};
  const MeasuredLaunch launch = FitLaunch(shot, {2.0, 0.0, 0.0, 0.0, 0.0}, Pool());
  EXPECT_FALSE(launch.ok);
}

}  // namespace
}  // namespace billiard::shot_fit
