#include "planner/players/ours_player.h"

#include <gtest/gtest.h>

#include "planner/choice/ball_in_hand.h"
#include "planner/choice/shot_choice.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/rules/rules.h"

namespace billiard::players {
namespace {

using OursTest = choice::testing::ChoiceTest;

// Ours (with the lookahead) is the choice: ChooseShot with the cue ball where it lies, ChooseWithBallInHand when
// the rules give ball in hand, the same to the last bit.
TEST_F(OursTest, IsTheChoiceWithTheCueBallWhereItLiesOrInHand) {
  const auto balls = TwoBalls();
  const choice::ChoiceOptions options = QuickChoice();
  Turn turn{table_, params_, balls, {false, rules::LegalTargets(options.rules, balls)}};
  batch::ThreadPool pool(2);
  const Ours ours;
  ExpectSameChoice(ours.Decide(turn, options, pool),
                   choice::ChooseShot(table_, params_, balls, options, pool));
  turn.constraints.ball_in_hand = true;
  const choice::ChoiceResult placed = ours.Decide(turn, options, pool);
  EXPECT_TRUE(placed.cue_placement);
  ExpectSameChoice(placed, choice::ChooseWithBallInHand(table_, params_, balls, options, pool));
}

// Without the lookahead, whatever the options say: each finalist scored by its probability
// alone, no position play; the choice with ChoiceOptions::lookahead off.
TEST_F(OursTest, WithoutTheLookaheadScoresByTheProbabilityAlone) {
  const auto balls = TwoBalls();
  choice::ChoiceOptions options = QuickChoice();
  ASSERT_TRUE(options.lookahead);
  batch::ThreadPool pool(2);
  const Ours no_lookahead(false);
  EXPECT_STREQ(no_lookahead.Name(), "no-lookahead");
  const choice::ChoiceResult r = no_lookahead.Decide(
      {table_, params_, balls, {false, rules::LegalTargets(options.rules, balls)}}, options, pool);
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
