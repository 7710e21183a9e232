#include "sim/shot_fit/strike_fit.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"
#include "tests/support/test_data.h"

namespace billiard::shot_fit {
namespace {

table::TableGeometry Carom() { return table::BuildTable(params::LoadTableSpec("carom-10ft")); }

TrackedShot ThreeBallsAtRest() {
  TrackedShot shot;
  shot.cue = 1;
  for (double x : {0.5, 1.0, 1.5}) shot.balls.push_back({"", {0.0, 0.02}, {{x, 0.7}, {x, 0.7}}});
  return shot;
}

// The strike vector reads back as the strike, with the elevation and the offsets of the balls
// whose starts are fitted; the differences' step below a level cue reads as the level cue.
TEST(StrikeVector, ReadsBackAsTheStrike) {
  FitOptions options;
  options.fit_elevation = true;
  options.fit_start = false;  // the cue ball's start only
  const TrackedShot shot = ThreeBallsAtRest();
  const Layout layout(options, 0.03, shot);
  ASSERT_EQ(layout.offset_balls, std::vector<std::size_t>{1});
  Strike s;
  s.stroke = {2.5, -1.2, 0.006, -0.003, 0.1};
  s.time = 0.013;
  s.start_offsets = {Eigen::Vector2d::Zero(), Eigen::Vector2d(0.001, -0.002)};
  const std::vector<double> x = ToVector(s, layout);
  ASSERT_EQ(x.size(), layout.size());
  const std::vector<double> expected = {2.5, -1.2, 0.2, -0.1, 0.013, 0.1, 0.001, -0.002};
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(x[k], expected[k], 1e-15) << k;
  const Strike back = FromVector(x.data(), layout);
  EXPECT_EQ(back.stroke.speed, s.stroke.speed);
  EXPECT_EQ(back.stroke.heading, s.stroke.heading);
  EXPECT_NEAR(back.stroke.tip_side, s.stroke.tip_side, 1e-18);
  EXPECT_NEAR(back.stroke.tip_height, s.stroke.tip_height, 1e-18);
  EXPECT_EQ(back.stroke.elevation, s.stroke.elevation);
  EXPECT_EQ(back.time, s.time);
  EXPECT_EQ(back.start_offsets, s.start_offsets);

  std::vector<double> below = x;
  below[5] = -1e-4;
  EXPECT_EQ(FromVector(below.data(), layout).stroke.elevation, 0.0);
}

// The impact lies between the cue ball's first sample and its second, a frame's slack before;
// the bounds hold a start offset within 4 mm and the tip within 0.6 r.
TEST(StrikeVector, BoundsTheImpactBetweenTheFirstSamplesAndTheStartsWithinMillimetres) {
  TrackedShot shot = ThreeBallsAtRest();
  shot.balls[1].t = {0.1, 0.12, 0.14};
  shot.balls[1].position.push_back({1.0, 0.7});
  const auto [lo, hi] = ImpactRange(shot);
  EXPECT_NEAR(lo, 0.08, 1e-15);
  EXPECT_EQ(hi, 0.12);
  const Layout layout(FitOptions{}, 0.03, shot);
  const StrikeBounds bounds = BoundsOf(layout, lo, hi);
  ASSERT_EQ(bounds.lo.size(), layout.size());
  ASSERT_EQ(bounds.hi.size(), layout.size());
  EXPECT_EQ(bounds.lo[4], lo);
  EXPECT_EQ(bounds.hi[4], hi);
  EXPECT_EQ(bounds.hi[2], 0.6);
  for (std::size_t k = layout.first_offset(); k < layout.size(); ++k) {
    EXPECT_EQ(bounds.lo[k], -0.004);
    EXPECT_EQ(bounds.hi[k], 0.004);
  }
  EXPECT_EQ(DifferenceSteps(layout, std::vector<double>(layout.size(), 2.0)).size(), layout.size());
}

// A shot whose cue ball is never seen moving has no strike: the fit reports none, and the
// balls at rest where they were seen follow it without error.
TEST(StrikeFit, AShotWhoseCueBallNeverMovesHasNoStrike) {
  const ShotFit fit =
      FitStrike(Carom(), params::LoadParameters("carom"), ThreeBallsAtRest(), FitOptions{});
  EXPECT_EQ(fit.strike.stroke.speed, 0.0);
  EXPECT_EQ(fit.rmse_cue, 0.0);
  EXPECT_EQ(fit.errors.rmse_all, 0.0);
}

TEST(StrikeFit, RecoversTheStrikeOfASimulatedShot) {
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom");
  Strike truth;
  truth.stroke.speed = 3.0;
  truth.stroke.heading = 0.35;
  truth.stroke.tip_side = 0.3 * p.ball.radius;
  truth.stroke.tip_height = 0.2 * p.ball.radius;
  truth.time = 0.011;
  const TrackedShot shot = SimulateTrackedShot(table, p, {{0.7, 0.4}, {2.0, 1.0}, {1.5, 0.3}}, 0,
                                               truth, 8.0, 0.02, 0.001, 0.002, 1);
  const ShotFit fit = FitStrike(table, p, shot, FitOptions{});
  EXPECT_LT(fit.rmse_cue, 0.003);
  EXPECT_NEAR(fit.strike.stroke.speed, truth.stroke.speed, 0.03);
  EXPECT_NEAR(fit.strike.stroke.heading, truth.stroke.heading, 1e-3);
}

// The real dev recordings (tailuge/billiards, GPL-3.0; shared/data/real-shots/README.md): they
// read as 60 shots of three balls, and the shipped carom set follows the first two to well
// within a ball's travel (the benchmark report has the distribution over all of them).
TEST(StrikeFit, FollowsRealShotsWithTheShippedCaromSet) {
  BILLIARD_TEST_DATA_OR_SKIP(path, "real-shots/three_cushion_dev.json");
  const TrackedShots tracked = ReadTrackedShots(path);
  ASSERT_EQ(tracked.shots.size(), 60u);
  for (const TrackedShot& shot : tracked.shots) EXPECT_EQ(shot.balls.size(), 3u);
  EXPECT_NE(tracked.source.find("tailuge/billiards"), std::string::npos);
  const table::TableGeometry table = Carom();
  const physics::ModelParameters p = params::LoadParameters("carom-fitted");
  for (int i = 0; i < 2; ++i) {
    const ShotFit fit = FitStrike(table, p, tracked.shots[i], FitOptions{});
    EXPECT_LT(fit.rmse_cue, 0.25) << "shot " << fit.id;
  }
}

}  // namespace
}  // namespace billiard::shot_fit
