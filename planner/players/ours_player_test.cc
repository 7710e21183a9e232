#include "planner/players/ours_player.h"

#include <gtest/gtest.h>

#include "planner/choice/ball_in_hand.h"
#include "planner/choice/shot_choice.h"
#include "planner/choice/testing/choice_test.h"
#include "planner/players/players.h"
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

// ours-one-level is the choice with the next shot valued in closed form (no second level),
// whatever the options say (the pot here likely enough that no safety is weighed).
TEST_F(OursTest, OneLevelValuesTheNextShotInClosedForm) {
  const auto balls = TwoBalls();
  choice::ChoiceOptions options = QuickChoice();
  ASSERT_TRUE(options.second_level);
  Turn turn{table_, params_, balls, {false, rules::LegalTargets(options.rules, balls)}};
  batch::ThreadPool pool(2);
  const choice::ChoiceResult one_level = MakePlayer(kOursOneLevel)->Decide(turn, options, pool);
  options.second_level = false;
  ExpectSameChoice(one_level, choice::ChooseShot(table_, params_, balls, options, pool));
}

// A long cut under the tournaments' noise whose miss leaves the 1 in the open, the pot unlikely.
class OursSafetyTest : public choice::testing::ChoiceTest {
 protected:
  std::vector<table::SceneBall> LongCut() const {
    const double l = table_.length, w = table_.width;
    return {table::AtRest(0, 0.6, w / 2), table::AtRest(1, l - 0.6, w / 2),
            table::AtRest(9, l - 0.4, 0.3)};
  }
  choice::ChoiceOptions Tournament() const {
    choice::ChoiceOptions options = QuickChoice();
    options.rules = rules::Rules::kNineBall;
    options.noise = params::LoadNoise("computational-pool");
    options.safety_screen_samples = 4;
    options.safety_samples = 16;
    return options;
  }
};

// There ours plays safe; ours-no-safety, round 3's chooser (no safeties, one level), plays the
// pot as the choice does without the second level.
TEST_F(OursSafetyTest, OursPlaysSafeWhereOursNoSafetyAttempts) {
  const auto balls = LongCut();
  choice::ChoiceOptions options = Tournament();
  const Turn turn{table_, params_, balls, {false, rules::LegalTargets(options.rules, balls)}};
  batch::ThreadPool pool(2);
  const choice::ChoiceResult safe = MakePlayer("ours")->Decide(turn, options, pool);
  ASSERT_TRUE(safe.safety) << safe.reason;
  EXPECT_EQ(safe.stroke(), &safe.safety->stroke);
  const choice::ChoiceResult attempt = MakePlayer(kOursNoSafety)->Decide(turn, options, pool);
  EXPECT_FALSE(attempt.safety);
  options.second_level = false;
  ExpectSameChoice(attempt, choice::ChooseShot(table_, params_, balls, options, pool));
}

// The same turn in a rack played alone (Turn::alone): no opponent takes the table after a miss,
// so ours weighs no safety and attempts the pot, to the last bit as its choice without safeties.
TEST_F(OursSafetyTest, AloneAttemptsWhereAgainstAnOpponentItPlaysSafe) {
  const auto balls = LongCut();
  const choice::ChoiceOptions options = Tournament();
  Turn turn{table_, params_, balls, {false, rules::LegalTargets(options.rules, balls)}};
  batch::ThreadPool pool(2);
  const Ours ours;
  ASSERT_TRUE(ours.Decide(turn, options, pool).safety);
  turn.alone = true;
  const choice::ChoiceResult alone = ours.Decide(turn, options, pool);
  EXPECT_FALSE(alone.safety);
  ExpectSameChoice(alone, choice::ChooseShot(table_, params_, balls, options, pool));
}

}  // namespace
}  // namespace billiard::players
