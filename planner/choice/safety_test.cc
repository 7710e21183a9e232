#include "planner/choice/safety.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "planner/choice/shot_choice.h"
#include "planner/choice/testing/choice_test.h"
#include "sim/cue/clearance.h"
#include "sim/cue/stroke_limits.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/robots.h"

namespace billiard::choice {
namespace {

class SafetyTest : public testing::ChoiceTest {
 protected:
  // A quick nine-ball choice under the tournaments' noise, its safety search small.
  static ChoiceOptions NineBall() {
    ChoiceOptions options = QuickChoice();
    options.rules = Rules::kNineBall;
    options.noise = params::LoadNoise("computational-pool");
    options.safety_screen_samples = 4;
    options.safety_finalists = 2;
    options.safety_samples = 16;
    return options;
  }
  // The choice of `balls`, weighed against a safety.
  ChoiceResult Decide(const std::vector<table::SceneBall>& balls, const ChoiceOptions& options,
                      int threads) const {
    batch::ThreadPool pool(threads);
    ChoiceResult r = ChooseShot(table_, params_, balls, options, pool);
    ConsiderSafety(table_, params_, balls, options, pool, &r);
    return r;
  }
  // The 1 at the far end across the table's width from the cue ball, the 9 beside its corner:
  // a long cut the noise makes unlikely, whose miss leaves the 1 in the open.
  std::vector<table::SceneBall> LongCut() const {
    const double l = table_.length, w = table_.width;
    return {table::AtRest(0, 0.6, w / 2), table::AtRest(1, l - 0.6, w / 2),
            table::AtRest(9, l - 0.4, 0.3)};
  }
  // The 1 a short roll from the corner pocket straight ahead, the 9 at the other end.
  std::vector<table::SceneBall> Sitter() const {
    const double l = table_.length, w = table_.width;
    return {table::AtRest(0, l - 0.5, 0.3), table::AtRest(1, l - 0.3, 0.3),
            table::AtRest(9, 0.4, w - 0.4)};
  }
  // The 1 straight along the table from the cue ball, the 5 on the line between them: the cue
  // ball is snookered on the 1.
  std::vector<table::SceneBall> Snookered() const {
    const double l = table_.length, w = table_.width;
    return {table::AtRest(0, 0.6, w / 2), table::AtRest(5, l / 2, w / 2),
            table::AtRest(1, l - 0.6, w / 2), table::AtRest(9, l - 0.4, 0.3)};
  }
  // A stroke that hit ball `first` and left `rest`.
  static StrokeResult Hit(int first, std::vector<table::SceneBall> rest) {
    StrokeResult r;
    r.struck = true;
    r.first_contact = first;
    r.rest = std::move(rest);
    return r;
  }
};

// The rules' fouls: a wrong first ball, a scratch, no ball to a rail or a pocket after contact.
TEST_F(SafetyTest, FoulsAsTheRulesSay) {
  const auto balls = LongCut();
  StrokeResult r = Hit(1, balls);
  EXPECT_TRUE(Fouls(balls, r, Rules::kNineBall));  // no rail after contact
  r.to_rail_after_contact = {1};
  EXPECT_FALSE(Fouls(balls, r, Rules::kNineBall));
  r.first_contact = 9;
  EXPECT_TRUE(Fouls(balls, r, Rules::kNineBall));  // the 9 before the 1
  EXPECT_FALSE(Fouls(balls, r, Rules::kAny));
  r.first_contact = 1;
  r.scratch = true;
  EXPECT_TRUE(Fouls(balls, r, Rules::kNineBall));
  r = Hit(1, balls);
  r.pocketed = {{1, "upper_right"}};
  EXPECT_FALSE(Fouls(balls, r, Rules::kNineBall));  // a pot needs no rail
}

// The scale's known ends: a foul that drops the 9 hands the opponent the rack (0); a legal
// nine-ball pot of the 9 wins it (1); under eight-ball an uncalled 8 loses it (0).
TEST_F(SafetyTest, WinChanceAtTheEndsOfTheRack) {
  const auto balls = LongCut();
  const std::vector<table::SceneBall> without_nine(balls.begin(), balls.begin() + 2);
  StrokeResult r = Hit(1, without_nine);
  r.pocketed = {{9, "lower_right"}};
  const ChoiceOptions nine = NineBall();
  EXPECT_EQ(WinChance(table_, params_.ball.radius, balls, r, std::nullopt, nine), 1.0);
  r.scratch = true;
  EXPECT_EQ(WinChance(table_, params_.ball.radius, balls, r, std::nullopt, nine), 0.0);
  ChoiceOptions eight = nine;
  eight.rules = Rules::kEightBallSolids;
  std::vector<table::SceneBall> eight_balls = balls;
  eight_balls[2].id = 8;
  r = Hit(1, {eight_balls[0], eight_balls[1]});
  r.pocketed = {{8, "lower_right"}};
  EXPECT_EQ(WinChance(table_, params_.ball.radius, eight_balls, r, std::nullopt, eight), 0.0);
  EXPECT_EQ(OpponentRules(Rules::kEightBallSolids), Rules::kEightBallStripes);
  EXPECT_EQ(OpponentRules(Rules::kNineBall), Rules::kNineBall);
}

// Every candidate heads into the legal ball (its line passes within a ball's width of the
// centre), on the grid of thicknesses and speeds; under eight-ball only the nearest targets.
TEST_F(SafetyTest, CandidatesHitTheLegalBall) {
  const auto balls = LongCut();
  const double r = params_.ball.radius;
  const std::vector<SafetyCandidate> nine = SafetyStrokes(table_, params_, balls, Rules::kNineBall);
  ASSERT_EQ(nine.size(), 28u);
  const double d = table_.length - 1.2;  // the 1 straight along +x from the cue ball
  for (const SafetyCandidate& c : nine) {
    EXPECT_EQ(c.target, 1);
    EXPECT_LT(std::abs(std::sin(c.stroke.heading)) * d, 2 * r);
    EXPECT_GT(std::cos(c.stroke.heading), 0);
  }
  const std::vector<SafetyCandidate> any = SafetyStrokes(table_, params_, balls, Rules::kAny);
  EXPECT_EQ(any.size(), 28u * kSafetyTargets);
}

// Snookered on the 1, the candidates also kick at it off the cushions: the direct strokes meet the
// 5 first; the kicks, found on the closed form, played without noise on the table's full model
// meet the 1 first at least half the time (the two models part a little in the slide and at
// the cushion).
TEST_F(SafetyTest, SnookeredCandidatesKickOffEachCushion) {
  const auto balls = Snookered();
  const double r = params_.ball.radius;
  const std::vector<SafetyCandidate> all = SafetyStrokes(table_, params_, balls, Rules::kNineBall);
  constexpr std::size_t kGrid = 28;  // thicknesses x speeds
  ASSERT_GT(all.size(), kGrid);
  const Motion motion = model_choice::TableMotion(params_);
  EXPECT_EQ(PlayToRest(table_, params_, balls, all[0].stroke, motion).first_contact, 5);
  int kicks_meeting_the_1 = 0;
  for (std::size_t k = kGrid; k < all.size(); ++k) {
    EXPECT_EQ(all[k].target, 1);
    kicks_meeting_the_1 +=
        PlayToRest(table_, params_, balls, all[k].stroke, motion).first_contact == 1;
  }
  std::cerr << kicks_meeting_the_1 << " of " << all.size() - kGrid << " kicks meet the 1 first"
            << std::endl;
  const int kicks = static_cast<int>(all.size() - kGrid);
  EXPECT_GE(kicks, 4);                        // off the two long cushions at least, at two speeds
  EXPECT_GE(2 * kicks_meeting_the_1, kicks);  // found on the closed form, most hold on the 5-DOF
}

// Snookered, the choice plays a kick at the 1 that seldom fouls (before the kicks: a safety on
// the 5's side that fouled every time, the only candidates being direct).
TEST_F(SafetyTest, SnookeredKicksRatherThanFoulForSure) {
  const ChoiceResult r = Decide(Snookered(), NineBall(), 2);
  std::cerr << r.reason << std::endl;
  ASSERT_TRUE(r.safety) << r.reason;
  EXPECT_EQ(r.safety->target, 1);
  EXPECT_LT(r.safety->foul_rate, 0.5) << r.reason;
}

// A safety from a cue ball a millimetre off the head rail: the cue comes over the rail, so every
// candidate is raised until it clears (by the cue's own geometry) and slowed until the ball stays
// on the cloth, and a robot that cannot raise its cue is left none.
TEST_F(SafetyTest, CandidatesAreRaisedOverTheRailOrDropped) {
  const double r = params_.ball.radius;
  const std::vector<table::SceneBall> balls = {
      table::AtRest(0, r + 1e-3, table_.width / 2),
      table::AtRest(1, table_.length / 2, table_.width / 2)};
  cue::Robot gantry = params::LoadRobot("gantry");
  const std::vector<SafetyCandidate> level =
      SafetyStrokes(table_, params_, balls, Rules::kNineBall);
  const std::vector<SafetyCandidate> raised = MakeableByCue(table_, params_, balls, gantry, level);
  ASSERT_FALSE(raised.empty());
  for (const SafetyCandidate& c : raised) {
    EXPECT_GT(c.stroke.elevation, 0.0);
    EXPECT_TRUE(cue::Clearance(table_, r, balls, 0, c.stroke, gantry).clears);
    EXPECT_LE(cue::HopHeight(c.stroke, {r + 1e-3, table_.width / 2}, params_),
              cue::TableMaxHop(params_) * (1 + 1e-9));
  }
  EXPECT_EQ(MakeableByCue(table_, params_, balls, std::nullopt, level).size(), level.size());
  gantry.elevation.max = 0.0;
  EXPECT_TRUE(MakeableByCue(table_, params_, balls, gantry, level).empty());
}

// A long cut the noise makes unlikely, its miss leaving the 1 in the open: a safety is played,
// hitting the 1 and seldom fouling, and it wins more racks than the attempt by the estimate.
TEST_F(SafetyTest, UnlikelyPotPlaysSafe) {
  const ChoiceResult r = Decide(LongCut(), NineBall(), 2);
  ASSERT_EQ(r.status, ChoiceStatus::kOk);
  ASSERT_LT(r.chosen()->reported().probability, NineBall().safety_below);
  ASSERT_TRUE(r.safety);
  EXPECT_EQ(r.safety->target, 1);
  EXPECT_LT(r.safety->foul_rate, 0.25);
  EXPECT_GT(r.safety->win, r.attempt_win);
  EXPECT_EQ(r.stroke(), &r.safety->stroke);
  EXPECT_NE(r.reason.find("playing safe"), std::string::npos);
}

// A sitter: with the search forced the attempt still wins on the scale; by default no search.
TEST_F(SafetyTest, SitterIsAttempted) {
  ChoiceOptions forced = NineBall();
  forced.safety_below = 2.0;
  const ChoiceResult searched = Decide(Sitter(), forced, 2);
  ASSERT_EQ(searched.status, ChoiceStatus::kOk);
  EXPECT_FALSE(searched.safety);
  EXPECT_GT(searched.attempt_win, 0.9);
  const ChoiceResult plain = Decide(Sitter(), NineBall(), 2);
  EXPECT_FALSE(plain.safety);
  EXPECT_EQ(plain.attempt_win, -1.0);  // not weighed: the pot is likely
}

// The same verdict on one thread as on three.
TEST_F(SafetyTest, SameVerdictWhateverTheThreads) {
  const ChoiceResult one = Decide(LongCut(), NineBall(), 1);
  const ChoiceResult three = Decide(LongCut(), NineBall(), 3);
  ASSERT_TRUE(one.safety && three.safety);
  EXPECT_EQ(one.safety->stroke.heading, three.safety->stroke.heading);
  EXPECT_EQ(one.safety->stroke.speed, three.safety->stroke.speed);
  EXPECT_EQ(one.safety->win, three.safety->win);
  EXPECT_EQ(one.attempt_win, three.attempt_win);
}

}  // namespace
}  // namespace billiard::choice
