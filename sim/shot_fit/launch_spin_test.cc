#include "sim/shot_fit/launch_spin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/closed_form.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::shot_fit {
namespace {

// The loop's camera: 30 frames a second, half a millimetre of error per coordinate.
constexpr double kFramePeriod = 1.0 / 30.0, kTrackingSd = 5e-4, kTrackDuration = 0.6;

// The pool set's balls on the default table, tracked as the loop's camera tracks them.
class LaunchSpinTest : public ::testing::Test {
 protected:
  MeasuredLaunch Launch(const SyntheticScene& scene, double noise, std::uint64_t seed) const {
    const TrackedShot shot = SimulateTrackedShot(table_, pool_, scene.starts, 0, scene.strike,
                                                 kTrackDuration, kFramePeriod, noise, 0.0, seed);
    return FitLaunch(shot, scene.strike.stroke, pool_);
  }
  std::vector<SyntheticScene> Strokes(int count, std::uint64_t seed) const {
    return LoopScenes(table_, pool_.ball.radius, count, seed);
  }

  const physics::ModelParameters pool_ = params::LoadParameters("pool");
  const table::TableGeometry table_ =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
};

// The slide's closed form (Jaroukh 2019, integrated in time) ends at 5/7 v0 + 2/7 s0 for any
// launch and spin on the table, the spin's component across the line included: a stunned ball
// rolls on at 5/7, a drawn one at 5/7 - 2/7, a rolling one keeps its speed.
TEST_F(LaunchSpinTest, RollingVelocityIsWhereTheSlidesClosedFormEnds) {
  const physics::ClosedFormParameters closed = physics::ClosedFormParameters::From(pool_);
  const double r = pool_.ball.radius;
  const double cases[][4] = {{1.0, 0.0, 0.0, 0.0},    {1.0, 0.0, 0.0, 1.0 / r},
                             {0.5, 0.2, 3.0, -20.0},  {-0.3, 0.8, -10.0, 4.0},
                             {2.0, -1.0, 0.0, -60.0}};
  for (const auto& c : cases) {
    const physics::BallState launch = physics::MakeBallState(1.0, 0.6, c[0], c[1], c[2], c[3], 0);
    const physics::ClosedFormTrajectory path(closed, launch);
    const Eigen::Vector2d v0(c[0], c[1]), s0(r * c[3], -r * c[2]);
    const Eigen::Vector2d rolled = path.slide_end_state().segment<2>(physics::kVx);
    EXPECT_LT((rolled - RollingVelocity(v0, s0)).norm(), 1e-12 * (1.0 + v0.norm()));
  }
  const Eigen::Vector2d v0(1.0, 0.0);
  EXPECT_NEAR(RollingVelocity(v0, Eigen::Vector2d::Zero()).x(), 5.0 / 7.0, 1e-15);
  EXPECT_NEAR(RollingVelocity(v0, -v0).x(), 3.0 / 7.0, 1e-15);
  EXPECT_NEAR(RollingVelocity(v0, v0).x(), 1.0, 1e-15);
}

// A centre hit stuns the ball (q = 0) and the natural roll's height, 0.4 r above, rolls it
// (q = 1): the cue's impulse J at height h gives m v = J and 2/5 m r^2 w = J h (Alciatore 2004,
// TP A.30), so q = r w / v = 5/2 h / r, whatever the speed.
TEST_F(LaunchSpinTest, SpinRatioOfIsFiveHalvesOfTheTipsHeight) {
  const double r = pool_.ball.radius;
  for (double h : {-0.4, -0.2, 0.0, 0.2, 0.4}) {
    const physics::CueStroke stroke{1.0, 0.3, 0.0, h * r, 0.0};
    EXPECT_NEAR(SpinRatioOf(stroke, pool_), 2.5 * h, 1e-12) << h;
  }
}

// From a noiseless track of the loop's strokes, the spin the frames show is the stroke's: the
// launch fit's v0 and v1 through v1 = 5/7 v0 + 2/7 s0 give back q for every stroke whose slide
// spans two frames or more and ends inside them (the stuns and draws, few follows at these
// speeds).
TEST_F(LaunchSpinTest, ANoiselessTrackGivesTheStrokesSpin) {
  int seen = 0;
  for (const SyntheticScene& scene : Strokes(40, 3)) {
    const LaunchSpin spin = SpinOf(Launch(scene, 0.0, 1));
    if (!spin.seen) continue;
    ++seen;
    EXPECT_NEAR(spin.ratio, SpinRatioOf(scene.strike.stroke, pool_), 1e-4)
        << scene.strike.stroke.tip_height / pool_.ball.radius;
  }
  EXPECT_GE(seen, 15);
}

// With the tracking's error, the spin's standard error bounds its error: the squared z-scores
// average 0.18 over the seen launches of these slow strokes (1 would be exact: the launch fit's
// covariance is conservative here, by about 2.3 in the standard error, which the noise fit's
// pooled tracking error takes up), and a millimetre of tip height (0.09 of q) stands clear of a
// typical launch's error.
TEST_F(LaunchSpinTest, TheSpinsStandardErrorBoundsItsError) {
  double sum = 0.0, sd = 0.0;
  int seen = 0;
  std::uint64_t seed = 100;
  for (const SyntheticScene& scene : Strokes(400, 4)) {
    const LaunchSpin spin = SpinOf(Launch(scene, kTrackingSd, ++seed));
    if (!spin.seen) continue;
    ++seen;
    const double z = (spin.ratio - SpinRatioOf(scene.strike.stroke, pool_)) / spin.ratio_sd;
    sum += z * z;
    sd += spin.ratio_sd;
  }
  ASSERT_GE(seen, 150);
  EXPECT_GT(sum / seen, 0.1);
  EXPECT_LT(sum / seen, 1.0);
  EXPECT_LT(sd / seen, 2.5e-3 / pool_.ball.radius);
}

// A launch whose frames end inside the slide shows no spin.
TEST(SpinOf, NotSeenWithoutTheRollingVelocity) {
  MeasuredLaunch launch;
  launch.ok = launch.launch_seen = true;
  launch.velocity = {1.0, 0.0};
  EXPECT_FALSE(SpinOf(launch).seen);
}

}  // namespace
}  // namespace billiard::shot_fit
