#include "planner/choice/lookahead.h"

#include <gtest/gtest.h>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using LookaheadTest = testing::ChoiceTest;

TEST_F(LookaheadTest, EasyEstimateSeesBlocksAndDistance) {
  const params::ExecutionNoise noise = params::LoadNoise("robot");
  const table::Pocket& corner = *table_.PocketNamed("upper_right");
  const double near = EasyPotEstimate(params_.ball.radius, StraightPot(0.3, 0.3), 1, corner, noise);
  const double far = EasyPotEstimate(params_.ball.radius, StraightPot(1.2, 1.0), 1, corner, noise);
  EXPECT_GT(near, 0.99);
  EXPECT_LT(far, near);
  auto blocked = StraightPot(0.6, 0.6);
  const Eigen::Vector2d mid = 0.5 * (blocked[0].state.segment<2>(physics::kX) +
                                     blocked[1].state.segment<2>(physics::kX));
  blocked.push_back(table::AtRest(2, mid.x(), mid.y()));
  EXPECT_EQ(EasyPotEstimate(params_.ball.radius, blocked, 1, corner, noise), 0.0);
}

// The table is symmetric about its long axis: a scene and its mirror image into the mirrored
// pocket look equally easy; a cut past the limit looks impossible.
TEST_F(LookaheadTest, MirroredScenesLookAlikeAndCutsHaveALimit) {
  const params::ExecutionNoise noise = params::LoadNoise("robot");
  const double r = params_.ball.radius, w = table_.width;
  const std::vector<table::SceneBall> scene = {table::AtRest(0, 1.0, 0.9), table::AtRest(4, 1.6, 0.7)};
  const std::vector<table::SceneBall> mirror = {table::AtRest(0, 1.0, w - 0.9), table::AtRest(4, 1.6, w - 0.7)};
  const double upper = EasyPotEstimate(r, scene, 4, *table_.PocketNamed("upper_right"), noise);
  const double lower = EasyPotEstimate(r, mirror, 4, *table_.PocketNamed("lower_right"), noise);
  ASSERT_GT(upper, 0.0);
  EXPECT_NEAR(upper, lower, 1e-9);
  // The cut here is near 50 degrees.
  EXPECT_EQ(EasyPotEstimate(r, scene, 4, *table_.PocketNamed("upper_right"), noise, 40.0), 0.0);
  EXPECT_EQ(EasyPotEstimate(r, scene, 4, *table_.PocketNamed("upper_right"), noise, 60.0), upper);
}

// The next shot of a table whose rack is over is worth a ball; without a cue ball nothing.
TEST_F(LookaheadTest, TheNextShotOfAFinishedRackIsWorthOne) {
  const params::ExecutionNoise noise = params::LoadNoise("robot");
  const double r = params_.ball.radius;
  EXPECT_EQ(BestNextShotValue(table_, r, {table::AtRest(0, 1, 0.5)}, Rules::kAny, noise), 1.0);
  const std::vector<table::SceneBall> no_nine = {table::AtRest(0, 1, 0.5), table::AtRest(3, 2, 0.9)};
  EXPECT_EQ(BestNextShotValue(table_, r, no_nine, Rules::kNineBall, noise), 1.0);
  const double any = BestNextShotValue(table_, r, no_nine, Rules::kAny, noise);
  EXPECT_GT(any, 0.0);
  EXPECT_LT(any, 1.0);
  EXPECT_EQ(BestNextShotValue(table_, r, {table::AtRest(3, 2, 0.9)}, Rules::kAny, noise), 0.0);
}

// The best over the legal targets: under nine-ball the lowest alone, however hard.
TEST_F(LookaheadTest, TheBestOverTheLegalTargets) {
  const params::ExecutionNoise noise = params::LoadNoise("robot");
  const double r = params_.ball.radius;
  auto balls = StraightPot(0.3, 0.3);
  balls[1].id = 5;
  balls.push_back(table::AtRest(2, 0.3, 0.2));
  balls.push_back(table::AtRest(9, 1.2, 0.6));
  double best_of_two = 0.0;
  for (const table::Pocket& p : table_.pockets) {
    best_of_two = std::max(best_of_two, EasyPotEstimate(r, balls, 2, p, noise));
  }
  EXPECT_EQ(BestNextShotValue(table_, r, balls, Rules::kNineBall, noise), best_of_two);
  EXPECT_GT(BestNextShotValue(table_, r, balls, Rules::kAny, noise), 0.99);  // the easy 5
}

}  // namespace
}  // namespace billiard::choice
