#include "planner/choice/candidates.h"

#include <gtest/gtest.h>

#include "planner/choice/testing/choice_test.h"

namespace billiard::choice {
namespace {

using CandidatesTest = testing::ChoiceTest;

// Every candidate is a legal target's pot in a pocket of the table, of a kind asked for, in
// target, pocket and kind order; under nine-ball only the lowest ball's.
TEST_F(CandidatesTest, EveryLegalTargetPocketAndKindInOrder) {
  const auto balls = TwoBalls();
  ChoiceOptions options;
  options.kinds = {pot::ShotKind::kDirect, pot::ShotKind::kBank};
  batch::ThreadPool pool(2);
  const std::vector<pot::PotPlan> any = PlanCandidates(table_, params_, balls, options, pool);
  ASSERT_FALSE(any.empty());
  auto order = [&](const pot::PotPlan& p) {
    int pocket = 0;
    while (table_.pockets[pocket].name != p.pocket) ++pocket;
    return std::make_tuple(p.ball, pocket, static_cast<int>(p.kind));
  };
  for (std::size_t i = 0; i < any.size(); ++i) {
    EXPECT_EQ(any[i].status, pot::PotStatus::kOk);
    EXPECT_TRUE(any[i].ball == 1 || any[i].ball == 2);
    if (i > 0) EXPECT_LT(order(any[i - 1]), order(any[i]));
  }
  EXPECT_EQ(any.front().ball, 1);
  EXPECT_EQ(any.back().ball, 2);
  options.rules = Rules::kNineBall;
  for (const pot::PotPlan& p : PlanCandidates(table_, params_, balls, options, pool)) {
    EXPECT_EQ(p.ball, 1);
  }
}

TEST_F(CandidatesTest, PlansOfPointIntoTheCandidates) {
  std::vector<Candidate> candidates(3);
  for (int i = 0; i < 3; ++i) candidates[i].plan.ball = i + 1;
  const std::vector<const pot::PotPlan*> plans = PlansOf(candidates, {2, 0});
  ASSERT_EQ(plans.size(), 2u);
  EXPECT_EQ(plans[0], &candidates[2].plan);
  EXPECT_EQ(plans[1], &candidates[0].plan);
}

// The reported probability is the confirmation's once there is one.
TEST(CandidateTest, ReportsTheConfirmedOnceThereIsOne) {
  Candidate c;
  c.full = Binomial(40, 64);
  EXPECT_EQ(&c.reported(), &c.full);
  c.confirmed = Binomial(150, 256);
  EXPECT_EQ(&c.reported(), &c.confirmed);
}

}  // namespace
}  // namespace billiard::choice
