#include "planner/players/no_lookahead_player.h"

#include <gtest/gtest.h>

#include "planner/choice/shot_choice.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/rules/rules.h"

namespace billiard::players {
namespace {

using NoLookaheadTest = choice::testing::ChoiceTest;

// The choice with the lookahead off, whatever the options say: each finalist scored by its
// probability alone, no position play.
TEST_F(NoLookaheadTest, ScoresByTheProbabilityAlone) {
  auto balls = StraightPot(0.5, 0.5);
  balls.push_back(Ball(2, 1.2, 0.5));
  choice::ChoiceOptions options = QuickChoice();
  ASSERT_TRUE(options.lookahead);
  const rules::Constraints open{false, rules::LegalTargets(options.rules, balls)};
  batch::ThreadPool pool(2);
  const choice::ChoiceResult r = NoLookahead().Decide(table_, params_, balls, open, options, pool);
  ASSERT_EQ(r.status, choice::ChoiceStatus::kOk) << r.reason;
  for (const choice::Candidate& c : r.candidates) {
    EXPECT_FALSE(c.position_target);
    if (c.finalist) EXPECT_EQ(c.score, c.full.probability);
  }
  options.lookahead = false;
  ExpectSameChoice(r, choice::ChooseShot(table_, params_, balls, options, pool));
}

}  // namespace
}  // namespace billiard::players
