#include "planner/choice/ball_in_hand.h"

#include <gtest/gtest.h>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using BallInHandTest = testing::ChoiceTest;

TEST_F(BallInHandTest, PlacesTheCueBallForALikelyPot) {
  const std::vector<table::SceneBall> balls = {table::AtRest(1, 1.6, 0.7), table::AtRest(2, 0.7, 0.4)};
  ChoiceOptions options;
  options.rules = Rules::kNineBall;
  options.samples = 16;
  options.screen_samples = 8;
  options.finalists = 2;
  options.placements = 2;
  options.kinds = {pot::ShotKind::kDirect};
  batch::ThreadPool pool(2);
  const ChoiceResult r = ChooseWithBallInHand(table_, params_, balls, options, pool);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  ASSERT_TRUE(r.cue_placement);
  EXPECT_TRUE(table_.OnSurface(*r.cue_placement, params_.ball.radius));
  for (const auto& b : balls) {
    EXPECT_GT((b.state.segment<2>(physics::kX) - *r.cue_placement).norm(), 2 * params_.ball.radius);
  }
  EXPECT_EQ(r.chosen()->plan.ball, 1);
  EXPECT_GT(r.chosen()->reported().probability, 0.9);
  EXPECT_TRUE(r.likely);
  // Only the placement played is confirmed (to its precision: a likely pot needs fewer).
  EXPECT_GE(r.chosen()->confirmed.samples, options.confirm_round);
  EXPECT_LE(r.chosen()->confirmed.samples, options.confirm_samples);
}

// A cue ball already on the table is lifted: where it lay does not block its own placement,
// and the result is the same as without it.
TEST_F(BallInHandTest, TheCueBallOnTheTableIsLifted) {
  const std::vector<table::SceneBall> without = {table::AtRest(1, 1.6, 0.7), table::AtRest(2, 0.7, 0.4)};
  std::vector<table::SceneBall> with = without;
  with.push_back(table::AtRest(0, 0.3, 0.3));
  ChoiceOptions options = QuickChoice();
  options.placements = 1;
  batch::ThreadPool pool(2);
  const ChoiceResult a = ChooseWithBallInHand(table_, params_, without, options, pool);
  const ChoiceResult b = ChooseWithBallInHand(table_, params_, with, options, pool);
  ASSERT_TRUE(a.cue_placement && b.cue_placement);
  EXPECT_EQ(*a.cue_placement, *b.cue_placement);
  ASSERT_TRUE(a.chosen() && b.chosen());
  EXPECT_EQ(a.chosen()->plan.ball, b.chosen()->plan.ball);
  EXPECT_EQ(a.chosen()->confirmed.successes, b.chosen()->confirmed.successes);
}

}  // namespace
}  // namespace billiard::choice
