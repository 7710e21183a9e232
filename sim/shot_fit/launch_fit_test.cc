#include "sim/shot_fit/launch_fit.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/closed_form.h"
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

// A long roll, struck with the robot's error (0.3 degree of heading, 2.5 % of speed, 0.8 mm of
// tip height and side) against the stroke it was told: the fit follows the ball for seconds, and
// neither the commanded line of the rolling resistance nor the commanded end of the slide may
// bend it (at 0.3 degree, the commanded line moves a 5 s roll's end by 4 mm; a draw's slide ends
// a tenth earlier or later). Noiseless, for the loop's spin styles: a stun's and a draw's
// launch and the velocity they roll on come back exactly; a follow's and a natural roll's slide
// is shorter than two frames, so their slide is the commanded one's and the velocity they roll
// on comes back to a tenth of a per cent, the path to a twenty-fifth of the camera's error.
TEST(FitLaunch, FollowsALongRollOfAStrokeOffItsCommand) {
  const double r = Pool().ball.radius;
  for (const double height : {0.0, -0.4, 0.4, 0.2}) {
    SyntheticScene scene;
    scene.starts = {{0.4, 0.65}};
    scene.strike.time = 0.01;
    const physics::CueStroke commanded{0.5, 0.0, 0.0, height * r, 0.0};
    scene.strike.stroke = commanded;
    scene.strike.stroke.speed *= 1.025;
    scene.strike.stroke.heading += 0.3 * M_PI / 180.0;
    scene.strike.stroke.tip_height += 0.8e-3;
    scene.strike.stroke.tip_side += 0.8e-3;
    const TrackedShot shot = SimulateTrackedShot(PoolTable(), Pool(), scene.starts, 0,
                                                 scene.strike, 6.0, kPeriod, 0.0, 0.0, 1);
    const MeasuredLaunch launch = FitLaunch(shot, commanded, Pool());
    ASSERT_TRUE(launch.ok && launch.rolling_seen) << launch.reason << height;
    EXPECT_GT(launch.samples * kPeriod, 2.0) << height;  // seconds of the roll fitted
    const physics::BallState played =
        physics::StrikeBall(scene.strike.stroke, scene.starts[0], Pool());
    const physics::ClosedFormTrajectory path(physics::ClosedFormParameters::From(Pool()), played);
    const Eigen::Vector2d rolling = path.slide_end_state().segment<2>(physics::kVx);
    const bool slides = height <= 0.0;
    EXPECT_EQ(launch.launch_seen, slides) << height;
    if (slides) {
      EXPECT_LT((launch.velocity - played.segment<2>(physics::kVx)).norm(), 1e-5) << height;
      EXPECT_LT((launch.rolling - rolling).norm(), 1e-5) << height;
      EXPECT_LT(launch.rms, 1e-6) << height;
    } else {
      EXPECT_LT((launch.rolling - rolling).norm(), 1e-3 * rolling.norm()) << height;
      EXPECT_LT(launch.rms, kNoise / 25.0) << height;
    }
  }
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
