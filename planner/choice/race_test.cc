#include "planner/choice/race.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/choice/screening.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/model_choice/model_choice.h"

namespace billiard::choice {
namespace {

using RaceTest = testing::ChoiceTest;

std::vector<Execution> Outcomes(int pots, int misses, double next_value) {
  std::vector<Execution> e(pots, Execution{true, next_value});
  e.resize(pots + misses);
  return e;
}

// Analytic cases: the mean is the choice's score p (1 + v); the half width z s / sqrt(n) with s
// the sample deviation; a stroke that always potted keeps the Agresti-Coull floor.
TEST_F(RaceTest, BoundsAreTheScoreAndItsStandardError) {
  const std::vector<Execution> half = Outcomes(8, 8, 0.5);  // X: 1.5 or 0, mean 0.75
  const ScoreBounds b = BoundsOf(half, true, 2.0);
  EXPECT_DOUBLE_EQ(b.mean, Score(TallyOf(half, 0, 16), true));
  const double s = std::sqrt(16 * 0.75 * 0.75 / 15);
  EXPECT_NEAR(b.high - b.mean, 2.0 * s / 4, 1e-12);
  EXPECT_NEAR(b.mean - b.low, 2.0 * s / 4, 1e-12);
  const ScoreBounds sure = BoundsOf(Outcomes(16, 0, 0.0), false, 2.0);
  EXPECT_DOUBLE_EQ(sure.mean, 1.0);
  const double p = 18.0 / 20;
  EXPECT_NEAR(sure.high - sure.low, 2 * 2.0 * std::sqrt(p * (1 - p)) / 4, 1e-12);
  // Four times the samples, half the width.
  const ScoreBounds more = BoundsOf(Outcomes(32, 32, 0.5), true, 2.0);
  EXPECT_NEAR((more.high - more.low) / (b.high - b.low), 0.5 * std::sqrt(64.0 / 63 * 15 / 16),
              1e-9);
}

// A near-certain straight pot raced against a hopeless one (the same ball to a far pocket under
// wild noise): the hopeless one stops after the first round, the race ends with one left, and
// every execution is the one a fixed-count run plays at its index, on 1 thread or 2.
TEST_F(RaceTest, TheBeatenStopAndEachSampleIsTheFixedRunsOwn) {
  const auto balls = StraightPot(0.4, 0.4);
  const pot::PotPlan sure = Plan(balls, 1, "upper_right");
  pot::PotPlan hopeless = sure;
  hopeless.stroke.heading += 0.3;  // 17 degrees off: the object ball misses the pocket
  ASSERT_EQ(sure.status, pot::PotStatus::kOk) << sure.reason;
  ChoiceOptions options;
  options.noise = HeadingNoise(0.05);
  options.samples = 64;
  options.race_round = 16;
  options.lookahead = false;
  const auto motion = model_choice::TableMotion(params_);
  batch::ThreadPool one(1), two(2);
  const auto raced = RaceFinalists(table_, params_, balls, {&hopeless, &sure}, options, motion, two);
  ASSERT_EQ(raced.size(), 2u);
  EXPECT_EQ(raced[0].size(), 16u);
  EXPECT_EQ(raced[1].size(), 16u);  // the one left needs no more to be chosen
  for (const Execution& e : raced[0]) EXPECT_FALSE(e.potted);
  const auto fixed = ExecuteAll(table_, params_, balls, {&sure}, 16, options, motion, false, one);
  for (std::size_t s = 0; s < fixed.size(); ++s) EXPECT_EQ(raced[1][s].potted, fixed[s].potted);
  const auto again = RaceFinalists(table_, params_, balls, {&hopeless, &sure}, options, motion, one);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(again[k].size(), raced[k].size());
}

// Two strokes as good as each other (the same plan twice) are never told apart: both run every
// round to options.samples.
TEST_F(RaceTest, EqualsRunToTheEnd) {
  const auto balls = StraightPot(0.6, 0.6);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ChoiceOptions options;
  options.noise = HeadingNoise(0.6);
  options.samples = 40;  // rounds of 16, 16 and 8
  batch::ThreadPool pool(2);
  const auto raced = RaceFinalists(table_, params_, balls, {&plan, &plan}, options,
                                   model_choice::TableMotion(params_), pool);
  EXPECT_EQ(raced[0].size(), 40u);
  EXPECT_EQ(raced[1].size(), 40u);
}

// The confirmation stops at the first round whose Agresti-Coull standard error meets the target:
// a sure pot after 64 executions (32 all potted: 0.038; 64: 0.021), a coin flip at the cap.
TEST_F(RaceTest, ConfirmationStopsAtItsPrecision) {
  const auto balls = StraightPot(0.4, 0.4);
  const pot::PotPlan sure = Plan(balls, 1, "upper_right");
  ChoiceOptions options;
  options.noise = HeadingNoise(0.01);
  batch::ThreadPool pool(2);
  const auto motion = model_choice::TableMotion(params_);
  const PotProbability p = ConfirmToPrecision(table_, params_, balls, sure, options, motion, pool);
  EXPECT_EQ(p.samples, 64);
  EXPECT_EQ(p.successes, 64);
  const auto far = StraightPot(0.6, 0.6);
  const pot::PotPlan coin = Plan(far, 1, "upper_right");
  options.noise = HeadingNoise(0.6);
  options.confirm_samples = 96;
  const PotProbability c = ConfirmToPrecision(table_, params_, far, coin, options, motion, pool);
  ASSERT_GT(c.probability, 0.2);  // a shot that neither always drops nor always misses
  ASSERT_LT(c.probability, 0.8);
  EXPECT_EQ(c.samples, 96);  // sqrt(0.25 / 100) = 0.05 > 0.03: the cap
}

}  // namespace
}  // namespace billiard::choice
