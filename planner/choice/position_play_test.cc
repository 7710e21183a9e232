#include "planner/choice/position_play.h"

#include <gtest/gtest.h>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using PositionPlayTest = testing::ChoiceTest;

// The best screened pots planned again toward a cue-ball target: the same ball, pocket and
// kind, the target on the table, no more than position_plans, none for a pot that never
// dropped.
TEST_F(PositionPlayTest, TheBestScreenedPotsPlannedAgainForPosition) {
  auto balls = TwoBalls();
  balls.push_back(table::AtRest(3, 0.6, 0.9));
  std::vector<Candidate> screened;
  for (const auto& [ball, pocket] : std::vector<std::pair<int, std::string>>{
           {1, "upper_right"}, {2, "lower_left"}, {3, "upper_left"}}) {
    Candidate c;
    c.plan = Plan(balls, ball, pocket);
    ASSERT_EQ(c.plan.status, pot::PotStatus::kOk) << ball << " " << c.plan.reason;
    c.screen_probability = c.score = 0.3 * ball;  // the 3 best, then the 2
    screened.push_back(c);
  }
  screened[0].screen_probability = screened[0].score = 0;  // the 1 never dropped
  ChoiceOptions options;
  options.position_plans = 1;
  batch::ThreadPool pool(2);
  const std::vector<Candidate> one =
      PositionCandidates(table_, params_, balls, screened, options, pool);
  ASSERT_LE(one.size(), 1u);
  options.position_plans = 3;
  const std::vector<Candidate> played =
      PositionCandidates(table_, params_, balls, screened, options, pool);
  ASSERT_FALSE(played.empty());
  for (const Candidate& c : played) {
    EXPECT_NE(c.plan.ball, 1);
    ASSERT_TRUE(c.position_target);
    EXPECT_TRUE(table_.OnSurface(*c.position_target, params_.ball.radius));
    const Candidate& from = screened[c.plan.ball - 1];
    EXPECT_EQ(c.plan.pocket, from.plan.pocket);
    EXPECT_EQ(c.plan.kind, from.plan.kind);
    EXPECT_EQ(c.screen_probability, 0.0);  // not screened yet
  }
  // In the screening's order: the 3 before the 2.
  for (std::size_t i = 1; i < played.size(); ++i) {
    EXPECT_GT(played[i - 1].plan.ball, played[i].plan.ball);
  }
}

}  // namespace
}  // namespace billiard::choice
