#include "planner/choice/monte_carlo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "planner/choice/scene_balls.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/model_choice/model_choice.h"
#include "sim/table/table_simulation.h"

namespace billiard::choice {
namespace {

using MonteCarloTest = testing::ChoiceTest;

TEST_F(MonteCarloTest, StraightShortPotIsNearlyCertainAndFallsWithNoise) {
  const auto balls = StraightPot(0.4, 0.4);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  batch::ThreadPool pool(2);
  const PotProbability tiny =
      EstimatePotProbability(table_, params_, balls, plan, HeadingNoise(0.01), 32, 1, pool);
  EXPECT_EQ(tiny.successes, 32);
  EXPECT_DOUBLE_EQ(tiny.stderr_, 0.0);
  // 3 degrees of heading turns the object ball by about 3 x 0.4 / (2 r) = 21 degrees: far
  // outside a corner's window at 0.4 m, so most miss.
  const PotProbability wild =
      EstimatePotProbability(table_, params_, balls, plan, HeadingNoise(3.0), 32, 1, pool);
  EXPECT_LT(wild.probability, 0.5);
  EXPECT_NEAR(wild.stderr_, std::sqrt(wild.probability * (1 - wild.probability) / 32), 1e-12);
}

// The spread of independent estimates is the binomial standard error each reports.
TEST_F(MonteCarloTest, StandardErrorMatchesTheSpreadOfEstimates) {
  const auto balls = StraightPot(0.6, 0.6);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  batch::ThreadPool pool(2);
  const int runs = 10, samples = 24;
  double sum = 0, sum_sq = 0, stderr_sum = 0;
  for (int seed = 1; seed <= runs; ++seed) {
    const PotProbability p =
        EstimatePotProbability(table_, params_, balls, plan, HeadingNoise(0.6), samples, seed, pool);
    sum += p.probability;
    sum_sq += p.probability * p.probability;
    stderr_sum += p.stderr_;
  }
  const double mean = sum / runs;
  ASSERT_GT(mean, 0.15);  // a shot that neither always drops nor always misses
  ASSERT_LT(mean, 0.85);
  const double spread = std::sqrt((sum_sq - runs * mean * mean) / (runs - 1));
  const double predicted = std::sqrt(mean * (1 - mean) / samples);
  EXPECT_GT(spread / predicted, 0.5);
  EXPECT_LT(spread / predicted, 1.6);
  EXPECT_NEAR(stderr_sum / runs / predicted, 1.0, 0.2);
}

TEST_F(MonteCarloTest, ScratchAndWrongContactAreNotPots) {
  // The cue ball alone, sent into the upper right pocket: a scratch, no contact.
  auto balls = StraightPot(0.4, 0.4);
  balls[1] = table::AtRest(1, 0.5, 0.3);
  const StrokeResult r =
      PlayToRest(table_, params_, balls, {2.0, std::atan2(1.0, 1.0), 0, 0, 0}, {});
  ASSERT_TRUE(r.struck);
  EXPECT_TRUE(r.scratch);
  EXPECT_EQ(r.first_contact, -1);
  EXPECT_FALSE(LegalPot(r, 1, "upper_right"));
  EXPECT_EQ(r.rest.size(), 1u);
}

// A ball left at rest past a pocket's mouth line drops into that pocket (the cue ball: a
// scratch); one short of the line stays.
TEST_F(MonteCarloTest, BallsHangingPastTheMouthDrop) {
  const table::Pocket& corner = *table_.PocketNamed("upper_right");
  const table::Pocket& side = *table_.PocketNamed("lower_middle");
  const Eigen::Vector2d past = corner.centre + 0.005 * corner.inward;
  const Eigen::Vector2d short_of = corner.centre - 0.005 * corner.inward;
  const Eigen::Vector2d cue = side.centre + 0.001 * side.inward;
  choice::StrokeResult result;
  result.pocketed = {{5, "lower_left"}};
  result.rest = {table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, past.x(), past.y()),
                 table::AtRest(4, short_of.x(), short_of.y()), table::AtRest(6, 1.0, 0.6)};
  DropHangingBalls(table_, &result);
  EXPECT_TRUE(result.scratch);
  const std::vector<std::pair<int, std::string>> pocketed = {{5, "lower_left"}, {3, "upper_right"}};
  EXPECT_EQ(result.pocketed, pocketed);
  ASSERT_EQ(result.rest.size(), 2u);
  EXPECT_EQ(result.rest[0].id, 4);
  EXPECT_EQ(result.rest[1].id, 6);
}

// The cue ball rolled softly down the upper right corner's diagonal: at some speed the
// simulation leaves it at rest between the mouth line and the capture line, in the jaws, which
// a real table drops and PlayToRest calls a scratch, as the table (planner/game/, the table
// simulator node) does; whatever rests short of the mouth line stays.
TEST_F(MonteCarloTest, PlayToRestDropsTheCueBallStoppingInTheJaws) {
  const std::vector<table::SceneBall> cue_alone = {StraightPot(0.4, 0.4)[0]};
  const double heading = std::atan2(1.0, 1.0);
  int hanging = 0;
  for (double speed = 0.30; speed < 1.2; speed += 0.01) {
    const physics::CueStroke stroke{speed, heading, 0, 0, 0};
    table::TableSimulation bare(table_, params_,
                                {table::Struck(0, stroke, Position(cue_alone[0]), params_)});
    bare.Run(60.0);
    const bool in_the_jaws =
        !bare.pocket(0) && table_.PocketPastMouth(bare.State(0).segment<2>(physics::kX));
    const StrokeResult r = PlayToRest(table_, params_, cue_alone, stroke, {});
    EXPECT_EQ(r.scratch, bare.pocket(0).has_value() || in_the_jaws) << speed;
    hanging += in_the_jaws;
  }
  EXPECT_GT(hanging, 0) << "no speed stops the cue ball in the jaws: the test shows nothing";
}

// FirstContact is PlayToRest's first contact, the table run only that far: over a fan of
// headings and speeds into two balls (the cue ball meeting the 1, the 2, both or neither, or
// dropping first), and -1 for a stroke no cue gives.
TEST_F(MonteCarloTest, FirstContactIsPlayToRestsOwn) {
  std::vector<table::SceneBall> balls = StraightPot(0.4, 0.6);
  balls.push_back(table::AtRest(2, 1.6, 0.9));
  std::set<int> met;
  for (double speed : {0.5, 1.5, 3.0}) {
    for (double heading = -M_PI; heading < M_PI; heading += 0.05) {
      const physics::CueStroke stroke{speed, heading, 0, 0, 0};
      const int first = FirstContact(table_, params_, balls, stroke);
      EXPECT_EQ(first, PlayToRest(table_, params_, balls, stroke, {}).first_contact)
          << speed << " m/s at " << heading;
      met.insert(first);
    }
  }
  EXPECT_EQ(met, (std::set<int>{-1, 1, 2}));
  EXPECT_EQ(FirstContact(table_, params_, balls, {2.0, 0.0, 2 * params_.ball.radius, 0, 0}), -1);
}

// A stroke no cue gives (the tip off the ball): not struck, the balls as they were.
TEST_F(MonteCarloTest, AStrokeTheCueCannotGiveIsNotStruck) {
  const auto balls = StraightPot(0.4, 0.4);
  const StrokeResult r = PlayToRest(table_, params_, balls, {2.0, 0.0, 2 * params_.ball.radius, 0, 0}, {});
  EXPECT_FALSE(r.struck);
  EXPECT_FALSE(LegalPot(r, 1, "upper_right"));
  ASSERT_EQ(r.rest.size(), balls.size());
  EXPECT_EQ(r.rest[1].state, balls[1].state);
}

// SplitMix64 seeds: the same for the same pair, distinct over many indices and seeds.
TEST(SampleSeedTest, IsAFunctionOfSeedAndIndexAlone) {
  EXPECT_EQ(SampleSeed(7, 3), SampleSeed(7, 3));
  std::set<std::uint64_t> seen;
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    for (std::uint64_t index = 0; index < 50; ++index) seen.insert(SampleSeed(seed, index));
  }
  EXPECT_EQ(seen.size(), 20u * 50u);
}

// Box-Muller's numbers have mean 0, variance 1 and the normal's fourth moment, 3 (to the
// sampling error of 20000 draws), and a seed repeats them.
TEST(NormalStreamTest, IsAStandardNormalThatASeedRepeats) {
  NormalStream a(5), b(5);
  const int n = 20000;
  double sum = 0, sum_sq = 0, sum_4 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = a.Next();
    EXPECT_EQ(z, b.Next());
    sum += z;
    sum_sq += z * z;
    sum_4 += z * z * z * z;
  }
  EXPECT_NEAR(sum / n, 0.0, 4 / std::sqrt(n));
  EXPECT_NEAR(sum_sq / n, 1.0, 4 * std::sqrt(2.0 / n));
  EXPECT_NEAR(sum_4 / n, 3.0, 4 * std::sqrt(96.0 / n));
}

TEST(BinomialTest, ProbabilityAndStandardError) {
  const PotProbability p = Binomial(12, 48);
  EXPECT_EQ(p.samples, 48);
  EXPECT_EQ(p.successes, 12);
  EXPECT_DOUBLE_EQ(p.probability, 0.25);
  EXPECT_DOUBLE_EQ(p.stderr_, std::sqrt(0.25 * 0.75 / 48));
  EXPECT_EQ(Binomial(0, 0).probability, 0.0);  // no samples: nothing known
  const std::vector<Execution> executions = {
      {true, 0.5, {}}, {false, 0, {}}, {true, 0.1, {}}, {false, 0, {}}};
  EXPECT_DOUBLE_EQ(PotRateOf(executions).probability, 0.5);
}

// A batch of two plans is each plan's own executions, side by side: execution s of a plan
// depends on (seed, s) alone, not on the batch it runs in or the threads.
TEST_F(MonteCarloTest, ABatchIsItsPlansExecutionsSideBySide) {
  const auto balls = StraightPot(0.6, 0.6);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  pot::PotPlan wide = plan;
  wide.stroke.heading += 0.004;
  ChoiceOptions options;
  options.noise = HeadingNoise(0.6);
  batch::ThreadPool two(2), one(1);
  const int samples = 12;
  const auto both = ExecuteAll(table_, params_, balls, {&plan, &wide}, samples, options, {}, true, two);
  const auto alone = ExecuteAll(table_, params_, balls, {&wide}, samples, options, {}, true, one);
  ASSERT_EQ(both.size(), 2u * samples);
  for (int s = 0; s < samples; ++s) {
    EXPECT_EQ(both[samples + s].potted, alone[s].potted);
    EXPECT_EQ(both[samples + s].next_value, alone[s].next_value);
    if (!both[s].potted) EXPECT_EQ(both[s].next_value, 0.0);
    // The rack is over when the only object ball drops: the next shot is worth a ball.
    if (both[s].potted) EXPECT_EQ(both[s].next_value, 1.0);
  }
}

// With the set's uncertainty, execution s plays on the table DrawnConstants gives for s, the
// same on one thread as on two; with sample_constants off, on the set's own values.
TEST_F(MonteCarloTest, ExecutionsPlayOnTheirDrawnTables) {
  const physics::ModelParameters uncertain = params::LoadParameters("pool");
  ASSERT_FALSE(uncertain.uncertainty.sd.empty());
  const auto balls = StraightPot(0.4, 0.4);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  ChoiceOptions options;
  options.noise = HeadingNoise(0.2);
  batch::ThreadPool two(2), one(1);
  const int samples = 16;
  const auto drawn = ExecuteAll(table_, uncertain, balls, {&plan}, samples, options, {}, false, two);
  const auto again = ExecuteAll(table_, uncertain, balls, {&plan}, samples, options, {}, false, one);
  options.sample_constants = false;
  const auto exact = ExecuteAll(table_, uncertain, balls, {&plan}, samples, options, {}, false, two);
  const auto reference = ExecuteAll(table_, params_, balls, {&plan}, samples, options, {}, false, two);
  for (int s = 0; s < samples; ++s) {
    physics::ModelParameters table_s = DrawnConstants(uncertain, true, options.seed, s);
    table_s.uncertainty = {};
    const auto one_sample = ExecuteRange(table_, table_s, balls, {&plan}, s, 1, options, {}, false, one);
    EXPECT_EQ(drawn[s].potted, one_sample[0].potted) << s;
    EXPECT_EQ(drawn[s].potted, again[s].potted) << s;
    EXPECT_EQ(exact[s].potted, reference[s].potted) << s;
  }
}

// Independent truth: without noise, the straight pot at 0.4 + 0.4 m drops for rolling
// resistance above a threshold d* (below it the cue ball follows into the pocket), found by
// bisection on exact tables on the motion the estimate plays. With d alone uncertain its Monte Carlo probability is then the
// normal's mass above d*, 1 - Phi((d* - d) / sd), within four binomial standard errors.
TEST_F(MonteCarloTest, AConstantsSpreadGivesTheNormalsMassWhereThePotDrops) {
  const auto balls = StraightPot(0.4, 0.4);
  const pot::PotPlan plan = Plan(balls, 1, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  auto pots_with_d = [&](double d) {
    physics::ModelParameters p = params_;
    p.contact.d = d;
    return LegalPot(PlayToRest(table_, p, balls, plan.stroke, model_choice::TableMotion(p)), 1,
                    "upper_right");
  };
  double fails = 0.3, pots = params_.contact.d;  // a third of the way down already scratches
  ASSERT_TRUE(pots_with_d(pots));
  ASSERT_FALSE(pots_with_d(fails));
  constexpr double kBisectionTolerance = 1e-4;
  while (pots - fails > kBisectionTolerance) {
    const double mid = 0.5 * (fails + pots);
    (pots_with_d(mid) ? pots : fails) = mid;
  }
  constexpr double kSd = 0.1;
  physics::ModelParameters uncertain = params_;
  uncertain.uncertainty.sd = {{"contact.d", kSd}};
  batch::ThreadPool pool(2);
  constexpr int kSamples = 400;
  const PotProbability p = EstimatePotProbability(table_, uncertain, balls, plan,
                                                  params::ExecutionNoise{}, kSamples, 3, pool);
  // d is drawn within [0, 1]: the normal truncated there (Phi of each end).
  auto phi = [&](double d) { return 0.5 * std::erfc(-(d - params_.contact.d) / (kSd * std::sqrt(2.0))); };
  const double expected = (phi(1.0) - phi(pots)) / (phi(1.0) - phi(0.0));
  ASSERT_GT(expected, 0.1);  // a threshold the spread reaches
  ASSERT_LT(expected, 0.99);
  EXPECT_NEAR(p.probability, expected, 4 * std::sqrt(expected * (1 - expected) / kSamples));
}

}  // namespace
}  // namespace billiard::choice
