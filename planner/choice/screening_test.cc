#include "planner/choice/screening.h"

#include <gtest/gtest.h>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using ScreeningTest = testing::ChoiceTest;

// Two candidates of three executions each: the k-th's pot rate, and the mean next-shot value
// over its pots alone.
TEST(TallyTest, PotRateAndTheMeanValueOfThePots) {
  const std::vector<Execution> e = {{true, 0.2}, {false, 0}, {true, 0.6},
                                    {false, 0}, {false, 0}, {false, 0}};
  const Tally first = TallyOf(e, 0, 3);
  EXPECT_EQ(first.pots.successes, 2);
  EXPECT_DOUBLE_EQ(first.pots.probability, 2.0 / 3);
  EXPECT_DOUBLE_EQ(first.next_shot_value, 0.4);
  const Tally second = TallyOf(e, 1, 3);
  EXPECT_EQ(second.pots.successes, 0);
  EXPECT_EQ(second.next_shot_value, 0.0);
  EXPECT_DOUBLE_EQ(Score(first, true), 2.0 / 3 * 1.4);  // p (1 + v)
  EXPECT_DOUBLE_EQ(Score(first, false), 2.0 / 3);       // p alone
}

// The score first; equal scores to the wider of the two heading margins' narrower side.
TEST(ScreenedBetterTest, ScoreFirstThenTheWiderWindow) {
  Candidate a, b;
  a.score = 0.9;
  b.score = 0.8;
  EXPECT_TRUE(ScreenedBetter(a, b));
  EXPECT_FALSE(ScreenedBetter(b, a));
  b.score = 0.9;
  a.plan.margin_left_deg = 0.5;
  a.plan.margin_right_deg = 2.0;
  b.plan.margin_left_deg = 1.0;
  b.plan.margin_right_deg = 1.0;
  EXPECT_TRUE(ScreenedBetter(b, a));
  EXPECT_FALSE(ScreenedBetter(a, b));
  EXPECT_FALSE(ScreenedBetter(a, a));  // a strict order
}

// Screening sets the screened candidates' probability and score from screen_samples
// executions each and leaves the others alone. The 1 half a metre from the pocket: from 0.4 m
// the planned pace lets the following cue ball stop in the jaws on the closed form, a scratch.
TEST_F(ScreeningTest, ScreensTheCandidatesAsked) {
  const auto balls = StraightPot(0.5, 0.4);
  std::vector<Candidate> candidates(2);
  candidates[0].plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(candidates[0].plan.status, pot::PotStatus::kOk) << candidates[0].plan.reason;
  candidates[1] = candidates[0];
  candidates[1].score = -1;
  ChoiceOptions options;
  options.noise = HeadingNoise(0.01);
  options.screen_samples = 8;
  batch::ThreadPool pool(2);
  EXPECT_EQ(Screen(table_, params_, balls, {0}, options, pool, &candidates), 8);
  EXPECT_EQ(candidates[0].screen_probability, 1.0);
  EXPECT_EQ(candidates[0].score, 2.0);  // every pot clears the table: worth a ball more
  EXPECT_EQ(candidates[1].score, -1);
  options.lookahead = false;
  Screen(table_, params_, balls, {1}, options, pool, &candidates);
  EXPECT_EQ(candidates[1].score, 1.0);
}

}  // namespace
}  // namespace billiard::choice
