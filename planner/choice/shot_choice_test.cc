#include "planner/choice/shot_choice.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::choice {
namespace {

constexpr double kDegree = M_PI / 180.0;

class ShotChoiceTest : public ::testing::Test {
 protected:
  ShotChoiceTest()
      : params_(params::LoadParameters("pool")),
        table_(table::BuildTable(params::LoadTableSpec("pool-9ft"))) {}

  table::SceneBall Ball(int id, double x, double y) const {
    table::SceneBall b;
    b.id = id;
    b.state.segment<2>(physics::kX) = Eigen::Vector2d(x, y);
    return b;
  }
  // The cue ball and ball 1 on the upper right corner pocket's diagonal, `object_back` and
  // `object_back + cue_back` from the pocket: a dead-straight pot.
  std::vector<table::SceneBall> StraightPot(double object_back, double cue_back) const {
    const Eigen::Vector2d corner = table_.PocketNamed("upper_right")->centre;
    const Eigen::Vector2d in = Eigen::Vector2d(1, 1).normalized();
    const Eigen::Vector2d o = corner - object_back * in, c = o - cue_back * in;
    return {Ball(0, c.x(), c.y()), Ball(1, o.x(), o.y())};
  }
  pot::PotPlan Plan(const std::vector<table::SceneBall>& balls, int ball, const std::string& pocket) {
    pot::PotRequest r;
    r.ball = ball;
    r.pocket = pocket;
    r.kind = pot::ShotKind::kDirect;
    return pot::PlanPot(table_, params_, balls, r);
  }
  static params::ExecutionNoise HeadingNoise(double deg) {
    params::ExecutionNoise n;
    n.heading = deg * kDegree;
    return n;
  }

  physics::ModelParameters params_;
  table::TableGeometry table_;
};

TEST_F(ShotChoiceTest, StraightShortPotIsNearlyCertainAndFallsWithNoise) {
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
TEST_F(ShotChoiceTest, StandardErrorMatchesTheSpreadOfEstimates) {
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
    EXPECT_EQ(c.confirmed.samples, options.confirm_samples);
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

TEST_F(ShotChoiceTest, ScratchAndWrongContactAreNotPots) {
  // The cue ball alone, sent into the upper right pocket: a scratch, no contact.
  auto balls = StraightPot(0.4, 0.4);
  const Eigen::Vector2d c = balls[0].state.segment<2>(physics::kX);
  balls[1] = Ball(1, 0.5, 0.3);
  const StrokeResult r =
      PlayToRest(table_, params_, balls, {2.0, std::atan2(1.0, 1.0), 0, 0, 0}, {});
  ASSERT_TRUE(r.struck);
  EXPECT_TRUE(r.scratch);
  EXPECT_EQ(r.first_contact, -1);
  EXPECT_FALSE(LegalPot(r, 1, "upper_right"));
  EXPECT_EQ(r.rest.size(), 1u);
  (void)c;
}

TEST_F(ShotChoiceTest, EasyEstimateSeesBlocksAndDistance) {
  const params::ExecutionNoise noise = params::LoadNoise("robot");
  const table::Pocket& corner = *table_.PocketNamed("upper_right");
  const double near = EasyPotEstimate(params_.ball.radius, StraightPot(0.3, 0.3), 1, corner, noise);
  const double far = EasyPotEstimate(params_.ball.radius, StraightPot(1.2, 1.0), 1, corner, noise);
  EXPECT_GT(near, 0.99);
  EXPECT_LT(far, near);
  auto blocked = StraightPot(0.6, 0.6);
  const Eigen::Vector2d mid = 0.5 * (blocked[0].state.segment<2>(physics::kX) +
                                     blocked[1].state.segment<2>(physics::kX));
  blocked.push_back(Ball(2, mid.x(), mid.y()));
  EXPECT_EQ(EasyPotEstimate(params_.ball.radius, blocked, 1, corner, noise), 0.0);
}

// Ball 3 sits near a corner; ball 1 is across the table. Any ball: the easy 3. Nine-ball: the
// 1, whatever it costs.
TEST_F(ShotChoiceTest, NineBallPlaysTheLowestBall) {
  auto balls = StraightPot(0.35, 0.35);
  balls[1].id = 3;
  balls.push_back(Ball(1, 0.5, 0.25));
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
  auto balls = StraightPot(0.5, 0.5);
  balls.push_back(Ball(2, 1.2, 0.5));
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

TEST_F(ShotChoiceTest, BallInHandPlacesTheCueBallForALikelyPot) {
  const std::vector<table::SceneBall> balls = {Ball(1, 1.6, 0.7), Ball(2, 0.7, 0.4)};
  ChoiceOptions options;
  options.rules = Rules::kNineBall;
  options.samples = 16;
  options.screen_samples = 8;
  options.finalists = 2;
  options.kinds = {pot::ShotKind::kDirect};
  batch::ThreadPool pool(2);
  const ChoiceResult r = ChooseWithBallInHand(table_, params_, balls, options, pool, 2);
  ASSERT_EQ(r.status, ChoiceStatus::kOk) << r.reason;
  ASSERT_TRUE(r.cue_placement);
  EXPECT_TRUE(table_.OnSurface(*r.cue_placement, params_.ball.radius));
  for (const auto& b : balls) {
    EXPECT_GT((b.state.segment<2>(physics::kX) - *r.cue_placement).norm(), 2 * params_.ball.radius);
  }
  EXPECT_EQ(r.chosen()->plan.ball, 1);
  EXPECT_GT(r.chosen()->reported().probability, 0.9);
  EXPECT_TRUE(r.likely);
}

TEST_F(ShotChoiceTest, RefusesWhatCannotBePlayed) {
  batch::ThreadPool pool(1);
  ChoiceOptions options;
  EXPECT_EQ(ChooseShot(table_, params_, {Ball(1, 1, 0.5)}, options, pool).status,
            ChoiceStatus::kInvalid);
  EXPECT_EQ(ChooseShot(table_, params_, {Ball(0, 1, 0.5)}, options, pool).status,
            ChoiceStatus::kNoTarget);
  EXPECT_EQ(ParseRules("nine-ball"), Rules::kNineBall);
  EXPECT_FALSE(ParseRules("snooker"));
}

}  // namespace
}  // namespace billiard::choice
