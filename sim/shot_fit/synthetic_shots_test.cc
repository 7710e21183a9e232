#include "sim/shot_fit/synthetic_shots.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

// A slow strike: the cue ball rolls well under a metre and stops.
Strike Slow() {
  Strike s;
  s.stroke.speed = 0.5;
  s.stroke.heading = 0.2;
  s.time = 0.005;
  return s;
}

// Without thinning, every frame is a sample; with it, a moving ball's kept samples lie at least
// the thinning apart (the last excepted), and a ball that never moves keeps its first and last.
TEST(SimulateTrackedShot, SamplesEveryFrameAndThinsWhereABallMovedLess) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  const std::vector<Eigen::Vector2d> starts = {{0.4, 0.3}, {2.5, 1.2}};  // ball 1 out of reach
  const TrackedShot every =
      SimulateTrackedShot(table, p, starts, 0, Slow(), 4.0, 0.02, 0.0, 0.0, 1);
  ASSERT_EQ(every.balls.size(), 2u);
  EXPECT_EQ(every.cue, 0u);
  EXPECT_EQ(every.balls[0].t.size(), 201u);
  EXPECT_EQ(every.balls[0].position.front(), starts[0]);
  EXPECT_NEAR(every.balls[0].t.back(), 4.0, 1e-12);

  constexpr double kThinning = 0.01;
  const TrackedShot thinned =
      SimulateTrackedShot(table, p, starts, 0, Slow(), 4.0, 0.02, 0.0, kThinning, 1);
  const TrackedBall& cue = thinned.balls[0];
  EXPECT_LT(cue.t.size(), every.balls[0].t.size());
  EXPECT_EQ(cue.t.front(), 0.0);
  EXPECT_EQ(cue.t.back(), every.balls[0].t.back());
  for (std::size_t s = 1; s + 1 < cue.t.size(); ++s)
    EXPECT_GE((cue.position[s] - cue.position[s - 1]).norm(), kThinning) << s;
  EXPECT_EQ(thinned.balls[1].t.size(), 2u);
  EXPECT_EQ(thinned.balls[1].position.front(), starts[1]);
  EXPECT_EQ(thinned.balls[1].position.back(), starts[1]);
}

// The noise is Gaussian of the given spread per coordinate: a ball at rest is seen scattered
// about its place by that much.
TEST(SimulateTrackedShot, ScattersTheSamplesByTheNoise) {
  constexpr double kNoise = 0.001;
  const Eigen::Vector2d at(2.0, 1.0);
  const TrackedShot shot =
      SimulateTrackedShot(Carom(), params::LoadParameters("carom"), {{0.4, 0.3}, at}, 0, Slow(),
                          8.0, 0.02, kNoise, 0.0, 9);
  const TrackedBall& still = shot.balls[1];
  double sum = 0.0, squares = 0.0;
  for (const Eigen::Vector2d& q : still.position) {
    sum += (q - at).x() + (q - at).y();
    squares += (q - at).squaredNorm();
  }
  const double n = 2.0 * static_cast<double>(still.position.size());
  EXPECT_LT(std::abs(sum / n), 4.0 * kNoise / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(squares / n), kNoise, 0.1 * kNoise);
}

// The scenes: three balls clear of each other (3 r) and of the cushions (2 r), the strike
// within its ranges, the same for the same seed.
TEST(SyntheticScenes, PlaceBallsClearAndStrikeWithinTheRanges) {
  const table::TableGeometry table = Carom();
  const double r = 0.03075;
  const std::vector<SyntheticScene> scenes = SyntheticScenes(table, r, 50, 8);
  ASSERT_EQ(scenes.size(), 50u);
  for (const SyntheticScene& scene : scenes) {
    ASSERT_EQ(scene.starts.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) {
      const Eigen::Vector2d& q = scene.starts[i];
      EXPECT_GE(q.x(), 2 * r);
      EXPECT_LE(q.x(), table.length - 2 * r);
      EXPECT_GE(q.y(), 2 * r);
      EXPECT_LE(q.y(), table.width - 2 * r);
      for (std::size_t j = i + 1; j < 3; ++j) EXPECT_GT((q - scene.starts[j]).norm(), 3 * r);
    }
    const Strike& s = scene.strike;
    EXPECT_GE(s.stroke.speed, 2.0);
    EXPECT_LE(s.stroke.speed, 4.0);
    EXPECT_LE(std::abs(s.stroke.tip_side), 0.4 * r);
    EXPECT_LE(std::abs(s.stroke.tip_height), 0.4 * r);
    EXPECT_GE(s.time, 0.0);
    EXPECT_LT(s.time, kSyntheticPeriod);
  }
  EXPECT_EQ(SyntheticScenes(table, r, 50, 8)[49].starts, scenes[49].starts);
  EXPECT_NE(SyntheticScenes(table, r, 50, 9)[49].starts, scenes[49].starts);
}

// The loop's strokes: one ball in the table's middle third, 0.25-0.6 m/s, no side, the four
// styles' tip heights in turn (or all natural), seeded.
TEST(LoopScenes, StrikeOneBallWithTheStylesInTurn) {
  const table::TableGeometry table = Carom();
  const double r = 0.03075;
  const std::vector<SyntheticScene> scenes = LoopScenes(table, r, 40, 8);
  ASSERT_EQ(scenes.size(), 40u);
  const double heights[] = {0.4, 0.0, 0.2, -0.4};
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    ASSERT_EQ(scenes[k].starts.size(), 1u);
    const Eigen::Vector2d& q = scenes[k].starts[0];
    EXPECT_GE(q.x(), table.length / 3);
    EXPECT_LE(q.x(), 2 * table.length / 3);
    EXPECT_GE(q.y(), table.width / 3);
    EXPECT_LE(q.y(), 2 * table.width / 3);
    const physics::CueStroke& s = scenes[k].strike.stroke;
    EXPECT_GE(s.speed, 0.25);
    EXPECT_LE(s.speed, 0.6);
    EXPECT_EQ(s.tip_side, 0.0);
    EXPECT_DOUBLE_EQ(s.tip_height, heights[k % 4] * r);
  }
  for (const SyntheticScene& scene : LoopScenes(table, r, 8, 8, true)) {
    EXPECT_DOUBLE_EQ(scene.strike.stroke.tip_height, 0.4 * r);
  }
  EXPECT_NE(LoopScenes(table, r, 2, 9)[1].starts, scenes[1].starts);
}

// The shots: one per scene, numbered from 1, ball 0 struck.
TEST(SyntheticShots, TrackOneShotPerSceneNumberedFromOne) {
  const std::vector<TrackedShot> shots =
      SyntheticShots(Carom(), params::LoadParameters("carom"), 3, 5);
  ASSERT_EQ(shots.size(), 3u);
  for (std::size_t i = 0; i < shots.size(); ++i) {
    EXPECT_EQ(shots[i].id, std::to_string(i + 1));
    EXPECT_EQ(shots[i].cue, 0u);
    EXPECT_EQ(shots[i].balls.size(), 3u);
    EXPECT_NEAR(shots[i].Duration(), 8.0, 1e-9);
  }
}

}  // namespace
}  // namespace billiard::shot_fit
