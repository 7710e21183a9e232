#include "planner/players/easiest_looking_player.h"

#include <gtest/gtest.h>

#include "planner/choice/easiest_looking.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/rules/rules.h"

namespace billiard::players {
namespace {

using EasiestLookingPlayerTest = choice::testing::ChoiceTest;

// The baseline, with ball in hand as the rules say.
TEST_F(EasiestLookingPlayerTest, IsTheBaselineWithBallInHandAsTheRulesSay) {
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5), table::AtRest(1, 1.6, 0.7),
                                               table::AtRest(2, 0.7, 0.4)};
  const choice::ChoiceOptions options;
  batch::ThreadPool pool(1);
  const EasiestLooking player;
  for (bool in_hand : {false, true}) {
    const Turn turn{table_, params_, balls, {in_hand, rules::LegalTargets(options.rules, balls)}};
    const choice::ChoiceResult r = player.Decide(turn, options, pool);
    EXPECT_EQ(r.cue_placement.has_value(), in_hand);
    ExpectSameChoice(r, choice::ChooseEasiestLooking(table_, params_, balls, options, in_hand));
  }
}

}  // namespace
}  // namespace billiard::players
