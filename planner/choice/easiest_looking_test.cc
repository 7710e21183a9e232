#include "planner/choice/easiest_looking.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/choice/lookahead.h"
#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using EasiestLookingTest = testing::ChoiceTest;

// A short straight pot and a long one: the short one, a direct pot, its score the estimate,
// its probability not estimated.
TEST_F(EasiestLookingTest, PlaysTheEasiestLookingPot) {
  auto balls = StraightPot(0.4, 0.4);
  balls.push_back(table::AtRest(2, 0.4, 0.3));
  ChoiceOptions options;
  const ChoiceResult r = ChooseEasiestLooking(table_, params_, balls, options, false);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  ASSERT_EQ(r.candidates.size(), 1u);
  const Candidate& c = r.candidates.front();
  EXPECT_EQ(c.plan.ball, 1);
  EXPECT_EQ(c.plan.pocket, "upper_right");
  EXPECT_EQ(c.plan.kind, pot::ShotKind::kDirect);
  EXPECT_EQ(c.score, EasyPotEstimate(params_.ball.radius, balls, 1,
                                     *table_.PocketNamed("upper_right"), options.noise));
  EXPECT_FALSE(c.finalist);
  EXPECT_EQ(c.full.samples, 0);
  EXPECT_EQ(r.likely, c.score >= options.likely);
  EXPECT_FALSE(r.cue_placement);
}

// With ball in hand the cue ball goes to the easiest-looking place, clear of the balls.
TEST_F(EasiestLookingTest, PlacesTheCueBallInHand) {
  const std::vector<table::SceneBall> balls = {table::AtRest(1, 1.6, 0.7), table::AtRest(2, 0.7, 0.4)};
  ChoiceOptions options;
  options.rules = Rules::kNineBall;
  const ChoiceResult r = ChooseEasiestLooking(table_, params_, balls, options, true);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  ASSERT_TRUE(r.cue_placement);
  EXPECT_TRUE(table_.OnSurface(*r.cue_placement, params_.ball.radius));
  EXPECT_EQ(r.chosen()->plan.ball, 1);
}

// No direct pot plans (every cut refused as too thin): the fallback hits the one legal ball
// full in the face.
TEST_F(EasiestLookingTest, NoDirectPotFallsBack) {
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 1.0, 0.5), table::AtRest(1, 1.5, 0.9)};
  ChoiceOptions options;
  options.pot.max_cut_deg = -1.0;
  const ChoiceResult r = ChooseEasiestLooking(table_, params_, balls, options, false);
  EXPECT_EQ(r.status, ChoiceStatus::kNoPlan);
  EXPECT_TRUE(r.candidates.empty());
  ASSERT_TRUE(r.fallback);
  EXPECT_DOUBLE_EQ(r.fallback->heading, std::atan2(0.4, 0.5));
}

}  // namespace
}  // namespace billiard::choice
