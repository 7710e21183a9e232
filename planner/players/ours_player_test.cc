#include "planner/players/ours_player.h"

#include <gtest/gtest.h>

#include "planner/choice/ball_in_hand.h"
#include "planner/choice/shot_choice.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/rules/rules.h"

namespace billiard::players {
namespace {

using OursTest = choice::testing::ChoiceTest;

// Ours is the choice: ChooseShot with the cue ball where it lies, ChooseWithBallInHand when
// the rules give ball in hand, the same to the last bit.
TEST_F(OursTest, IsTheChoiceWithTheCueBallWhereItLiesOrInHand) {
  auto balls = StraightPot(0.5, 0.5);
  balls.push_back(Ball(2, 1.2, 0.5));
  const choice::ChoiceOptions options = QuickChoice();
  const rules::Constraints open{false, rules::LegalTargets(options.rules, balls)};
  batch::ThreadPool pool(2);
  const Ours ours;
  ExpectSameChoice(ours.Decide(table_, params_, balls, open, options, pool),
                   choice::ChooseShot(table_, params_, balls, options, pool));
  rules::Constraints in_hand = open;
  in_hand.ball_in_hand = true;
  const choice::ChoiceResult placed = ours.Decide(table_, params_, balls, in_hand, options, pool);
  EXPECT_TRUE(placed.cue_placement);
  ExpectSameChoice(placed, choice::ChooseWithBallInHand(table_, params_, balls, options, pool));
}

}  // namespace
}  // namespace billiard::players
