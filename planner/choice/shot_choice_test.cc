#include "planner/choice/shot_choice.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using ShotChoiceTest = testing::ChoiceTest;

// The reported probability comes from executions of its own, not from those that chose the
// shot: over seeded choices it agrees with an independent estimate of each chosen stroke.
TEST_F(ShotChoiceTest, ReportedProbabilityIsTheConfirmationsAndUnbiased) {
  const auto balls = StraightPot(0.6, 0.6);
  ChoiceOptions options;
  options.noise = HeadingNoise(0.6);
  options.samples = 16;
  options.screen_samples = 8;
  options.finalists = 2;
  options.confirm_samples = 96;
  options.kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank};
  batch::ThreadPool pool(2);
  const int choices = 6, truth_samples = 192;
  double reported_sum = 0, truth_sum = 0, variance_sum = 0;
  for (int seed = 1; seed <= choices; ++seed) {
    options.seed = seed;
    const ChoiceResult r = ChooseShot(table_, params_, balls, options, pool);
    ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
    const Candidate& c = *r.chosen();
    EXPECT_GT(c.confirmed.samples, 0);
    EXPECT_LE(c.confirmed.samples, options.confirm_samples);
    EXPECT_EQ(&c.reported(), &c.confirmed);
    const PotProbability truth = EstimatePotProbability(table_, params_, balls, c.plan, options.noise,
                                                        truth_samples, 1000 + seed, pool);
    reported_sum += c.confirmed.probability;
    truth_sum += truth.probability;
    variance_sum += c.confirmed.stderr_ * c.confirmed.stderr_ + truth.stderr_ * truth.stderr_;
  }
  ASSERT_GT(truth_sum / choices, 0.15);  // a shot that neither always drops nor always misses
  ASSERT_LT(truth_sum / choices, 0.85);
  EXPECT_LT(std::abs(reported_sum - truth_sum) / choices, 3 * std::sqrt(variance_sum) / choices);
  options.confirm_samples = 0;  // off: the finalists' own estimate is reported
  const ChoiceResult unconfirmed = ChooseShot(table_, params_, balls, options, pool);
  EXPECT_EQ(&unconfirmed.chosen()->reported(), &unconfirmed.chosen()->full);
}

// Ball 3 sits near a corner; ball 1 is across the table. Any ball: the easy 3. Nine-ball: the
// 1, whatever it costs.
TEST_F(ShotChoiceTest, NineBallPlaysTheLowestBall) {
  auto balls = StraightPot(0.35, 0.35);
  balls[1].id = 3;
  balls.push_back(table::AtRest(1, 0.5, 0.25));
  ChoiceOptions options;
  options.samples = 16;
  options.screen_samples = 8;
  options.finalists = 2;
  options.kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank};
  batch::ThreadPool pool(2);
  const ChoiceResult any = ChooseShot(table_, params_, balls, options, pool);
  ASSERT_EQ(any.status, ChoiceStatus::kOk) << any.reason;
  // (The dead-straight pot of the 3 is refused: the cue ball would follow it in.)
  EXPECT_EQ(any.chosen()->plan.ball, 3);
  options.rules = Rules::kNineBall;
  const ChoiceResult nine = ChooseShot(table_, params_, balls, options, pool);
  ASSERT_NE(nine.chosen(), nullptr) << nine.reason;
  for (const Candidate& c : nine.candidates) EXPECT_EQ(c.plan.ball, 1);
}

TEST_F(ShotChoiceTest, SameChoiceOnOneThreadOrTwo) {
  const auto balls = TwoBalls();
  ChoiceOptions options;
  options.samples = 12;
  options.screen_samples = 6;
  options.finalists = 3;
  options.kinds = {pot::ShotKind::kDirect};
  batch::ThreadPool one(1), two(2);
  const ChoiceResult a = ChooseShot(table_, params_, balls, options, one);
  const ChoiceResult b = ChooseShot(table_, params_, balls, options, two);
  ASSERT_EQ(a.candidates.size(), b.candidates.size());
  ASSERT_FALSE(a.candidates.empty());
  for (std::size_t i = 0; i < a.candidates.size(); ++i) {
    EXPECT_EQ(a.candidates[i].plan.ball, b.candidates[i].plan.ball);
    EXPECT_EQ(a.candidates[i].plan.pocket, b.candidates[i].plan.pocket);
    EXPECT_EQ(a.candidates[i].full.successes, b.candidates[i].full.successes);
    EXPECT_EQ(a.candidates[i].confirmed.successes, b.candidates[i].confirmed.successes);
    EXPECT_EQ(a.candidates[i].next_shot_value, b.candidates[i].next_shot_value);
    EXPECT_EQ(a.candidates[i].score, b.candidates[i].score);
  }
}

// The named steps' contract: the finalists first (those that ran the race furthest, then best
// scored), each with its full-model estimate and score p (1 + v); the others after them; the
// chosen alone confirmed.
TEST_F(ShotChoiceTest, FinalistsFirstByScoreAndOnlyTheChosenConfirmed) {
  const auto balls = TwoBalls();
  ChoiceOptions options = QuickChoice();
  options.kinds.push_back(pot::ShotKind::kBank);
  batch::ThreadPool pool(2);
  const ChoiceResult r = ChooseShot(table_, params_, balls, options, pool);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  ASSERT_GT(r.candidates.size(), 2u);
  for (std::size_t i = 0; i < r.candidates.size(); ++i) {
    const Candidate& c = r.candidates[i];
    EXPECT_EQ(c.finalist, static_cast<int>(i) < options.finalists) << i;
    EXPECT_EQ(c.confirmed.samples > 0, i == 0) << i;
    EXPECT_LE(c.confirmed.samples, options.confirm_samples) << i;
    if (!c.finalist) continue;
    EXPECT_GT(c.full.samples, 0) << i;
    EXPECT_LE(c.full.samples, options.samples) << i;
    EXPECT_DOUBLE_EQ(c.score, c.full.probability * (1 + c.next_shot_value));
    if (i == 0) continue;
    const Candidate& before = r.candidates[i - 1];
    EXPECT_GE(before.full.samples, c.full.samples) << i;
    if (before.full.samples == c.full.samples) EXPECT_GE(before.score, c.score) << i;
  }
  EXPECT_EQ(r.likely, r.chosen()->reported().probability >= options.likely);
  EXPECT_GT(r.simulations, 0);
}

// The candidates' margins only rank them, walked to a cap; the chosen one's is stated as the pot
// planner states it: every heading 0.01 degree apart inside it pots legally on the truth, the
// next one out does not. The others' are left as ranked, and so is the chosen one's when off.
TEST_F(ShotChoiceTest, TheChosenPotsMarginIsStatedInFull) {
  const auto balls = TwoBalls();
  ChoiceOptions options = QuickChoice();
  options.margin_cap_deg = 0.02;
  batch::ThreadPool pool(2);
  const ChoiceResult r = ChooseShot(table_, params_, balls, options, pool);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  const pot::PotPlan& chosen = r.chosen()->plan;
  ASSERT_GT(std::min(chosen.margin_left_deg, chosen.margin_right_deg), 0.02) << "past the cap";
  constexpr double kGrid = 0.01 * M_PI / 180.0;
  for (const auto& [side, margin] :
       {std::pair{1.0, chosen.margin_left_deg}, {-1.0, chosen.margin_right_deg}}) {
    const int steps = static_cast<int>(std::lround(margin / 0.01));
    for (int j = 1; j <= steps + 1; ++j) {
      physics::CueStroke s = chosen.stroke;
      s.heading += side * j * kGrid;
      EXPECT_EQ(pot::PlayStroke(table_, params_, balls, chosen.ball, chosen.pocket, s).legal, j <= steps)
          << j << " steps x " << side;
    }
  }
  for (std::size_t i = 1; i < r.candidates.size(); ++i) {
    EXPECT_LE(r.candidates[i].plan.margin_left_deg, 0.02 + 1e-9) << i;
  }
  options.state_margin = false;
  const ChoiceResult ranked = ChooseShot(table_, params_, balls, options, pool);
  ExpectSameChoice(r, ranked);
  EXPECT_NEAR(ranked.chosen()->plan.margin_left_deg, 0.02, 1e-9);
  EXPECT_LT(ranked.simulations, r.simulations);
}

TEST_F(ShotChoiceTest, RefusesWhatCannotBePlayed) {
  batch::ThreadPool pool(1);
  ChoiceOptions options;
  EXPECT_EQ(ChooseShot(table_, params_, {table::AtRest(1, 1, 0.5)}, options, pool).status,
            ChoiceStatus::kInvalid);
  EXPECT_EQ(ChooseShot(table_, params_, {table::AtRest(0, 1, 0.5)}, options, pool).status,
            ChoiceStatus::kNoTarget);
}

}  // namespace
}  // namespace billiard::choice
