#include "planner/game/game.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "planner/choice/testing/choice_test.h"

namespace billiard::game {
namespace {

class GameTest : public choice::testing::ChoiceTest {
 protected:
  GameTest() {
    options_.choice.samples = 12;
    options_.choice.screen_samples = 6;
    options_.choice.finalists = 2;
    options_.choice.kinds = {pot::ShotKind::kDirect};
    options_.choice.placements = 2;
    options_.shot_limit = 8;
  }

  GameOptions options_;
};

// A player that plays the strokes it is given, one a shot (the last again when they run out),
// and remembers what the rules allowed each shot.
class Scripted final : public players::Player {
 public:
  explicit Scripted(std::vector<physics::CueStroke> strokes) : strokes_(std::move(strokes)) {}
  const char* Name() const override { return "scripted"; }
  choice::ChoiceResult Decide(const players::Turn& turn, const choice::ChoiceOptions&,
                              batch::ThreadPool&) const override {
    seen_.push_back(turn.constraints);
    choice::ChoiceResult r;
    r.status = choice::ChoiceStatus::kNoPlan;
    r.fallback = strokes_[std::min(seen_.size(), strokes_.size()) - 1];
    return r;
  }
  const std::vector<rules::Constraints>& seen() const { return seen_; }

 private:
  std::vector<physics::CueStroke> strokes_;
  mutable std::vector<rules::Constraints> seen_;
};

// Three open balls from ball in hand: cleared, and the summary adds up the shots. Twenty shots
// at most: a miss can leave the last ball where no direct pot plans, and the fallback strokes
// then take a few shots to free it (4 of the 9 this game takes).
TEST_F(GameTest, ClearsAnOpenTableAndCountsWhatHappened) {
  const std::vector<table::SceneBall> balls = {table::AtRest(1, 1.9, 0.9), table::AtRest(2, 0.8, 0.35),
                                               table::AtRest(3, 1.3, 0.7)};
  options_.ball_in_hand = true;
  options_.shot_limit = 20;
  batch::ThreadPool pool(2);
  const GameRecord game = PlayGame(table_, params_, balls, options_, pool);
  const GameSummary& s = game.summary;
  EXPECT_TRUE(s.cleared);
  EXPECT_TRUE(game.shots.front().cue_placement);
  EXPECT_EQ(s.shots, static_cast<int>(game.shots.size()));
  EXPECT_LE(s.pots, s.attempts);
  EXPECT_EQ(s.balls_potted, 3);
  int potted = 0, fouls = 0;
  for (const ShotRecord& r : game.shots) {
    if (!r.foul) potted += static_cast<int>(r.potted.size());
    fouls += r.foul;
  }
  EXPECT_EQ(potted, s.balls_potted);
  EXPECT_EQ(fouls, s.fouls);
  EXPECT_EQ(s.run_out, s.visits == 1);
  EXPECT_EQ(s.end, GameEnd::kCleared);
}

TEST_F(GameTest, SameGameOnOneThreadOrTwo) {
  const auto balls = SeededNineBallLayout(table_, params_.ball.radius, 5);
  options_.choice.rules = rules::Rules::kNineBall;
  options_.shot_limit = 3;
  batch::ThreadPool one(1), two(2);
  const GameRecord a = PlayGame(table_, params_, balls, options_, one);
  const GameRecord b = PlayGame(table_, params_, balls, options_, two);
  ASSERT_EQ(a.shots.size(), b.shots.size());
  for (std::size_t i = 0; i < a.shots.size(); ++i) {
    EXPECT_EQ(a.shots[i].ball, b.shots[i].ball);
    EXPECT_EQ(a.shots[i].pocket, b.shots[i].pocket);
    EXPECT_EQ(a.shots[i].potted, b.shots[i].potted);
    EXPECT_EQ(a.shots[i].predicted, b.shots[i].predicted);
  }
  ASSERT_EQ(a.final_balls.size(), b.final_balls.size());
  for (std::size_t i = 0; i < a.final_balls.size(); ++i) {
    EXPECT_EQ(a.final_balls[i].state, b.final_balls[i].state);
  }
}

// Nine-ball: every called ball is the lowest on the table when it is called.
TEST_F(GameTest, NineBallCallsTheLowestBall) {
  const auto balls = SeededNineBallLayout(table_, params_.ball.radius, 11);
  ASSERT_EQ(balls.size(), 9u);
  options_.choice.rules = rules::Rules::kNineBall;
  options_.ball_in_hand = true;
  options_.shot_limit = 4;
  batch::ThreadPool pool(2);
  const GameRecord game = PlayGame(table_, params_, balls, options_, pool);
  std::vector<int> on_table = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  for (const ShotRecord& r : game.shots) {
    if (r.ball >= 0) {
      EXPECT_EQ(r.ball, on_table.front());
    }
    if (r.foul) continue;
    for (int id : r.potted) on_table.erase(std::find(on_table.begin(), on_table.end(), id));
  }
}

TEST_F(GameTest, SeededLayoutsAreClearAndRepeatable) {
  const auto a = SeededNineBallLayout(table_, params_.ball.radius, 3);
  const auto b = SeededNineBallLayout(table_, params_.ball.radius, 3);
  ASSERT_EQ(a.size(), 9u);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].state, b[i].state);
    EXPECT_TRUE(table_.OnSurface(a[i].state.segment<2>(physics::kX), 3 * params_.ball.radius));
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_GE((a[i].state - a[j].state).norm(), 4 * params_.ball.radius);
    }
  }
}

// A shot that touches nothing is a foul: the next shot has ball in hand and starts a visit;
// the player is told so, and the game records the reason.
TEST_F(GameTest, AFoulGivesTheNextShotBallInHand) {
  const std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5), table::AtRest(1, 2.0, 1.0)};
  auto player = std::make_shared<Scripted>(std::vector<physics::CueStroke>{{0.3, M_PI, 0, 0, 0}});
  options_.player = player;
  options_.execution = params::ExecutionNoise{};  // the strokes played as given
  options_.shot_limit = 2;
  batch::ThreadPool pool(1);
  const GameRecord game = PlayGame(table_, params_, balls, options_, pool);
  ASSERT_EQ(game.shots.size(), 2u);
  EXPECT_TRUE(game.shots[0].foul);
  EXPECT_EQ(game.shots[0].foul_reason, "no contact");
  EXPECT_EQ(game.shots[0].status, "no_plan");
  EXPECT_FALSE(game.shots[0].ball_in_hand);
  EXPECT_TRUE(game.shots[1].ball_in_hand);
  EXPECT_EQ(game.shots[1].visit, 2);
  ASSERT_EQ(player->seen().size(), 2u);
  EXPECT_FALSE(player->seen()[0].ball_in_hand);
  EXPECT_TRUE(player->seen()[1].ball_in_hand);
  EXPECT_EQ(player->seen()[0].legal_targets, (std::vector<int>{1}));
  EXPECT_EQ(game.summary.fouls, 2);
  EXPECT_FALSE(game.summary.cleared);
  EXPECT_EQ(game.summary.end, GameEnd::kShotLimit);
}

// The 1, the only legal ball under nine-ball, behind a wall of three: no direct pot plans. The
// shot is recorded as no_plan with the choice's reason, the fallback (at the 1 full) is played
// and judged (it meets the wall first: a foul), and the rack goes on from ball in hand.
TEST_F(GameTest, WhenNothingPlansTheFallbackIsPlayedAndTheRackGoesOn) {
  const double y = 0.5 * table_.width;
  const std::vector<table::SceneBall> balls = {
      table::AtRest(0, 0.6, y),        table::AtRest(1, 1.3, y),
      table::AtRest(2, 0.9, y),        table::AtRest(3, 0.9, y - 0.06),
      table::AtRest(4, 0.9, y + 0.06)};
  options_.choice.rules = rules::Rules::kNineBall;
  options_.shot_limit = 2;
  batch::ThreadPool pool(2);
  const GameRecord game = PlayGame(table_, params_, balls, options_, pool);
  ASSERT_EQ(game.shots.size(), 2u);
  const ShotRecord& first = game.shots[0];
  EXPECT_EQ(first.status, "no_plan");
  EXPECT_NE(first.reason.find("no pot of a legal ball plans"), std::string::npos) << first.reason;
  EXPECT_EQ(first.ball, -1);
  EXPECT_EQ(first.first_contact, 2);
  EXPECT_TRUE(first.foul);
  EXPECT_TRUE(game.shots[1].ball_in_hand);
  EXPECT_EQ(game.summary.shots, 2);
  EXPECT_EQ(game.summary.end, GameEnd::kShotLimit);
}

// Under nine-ball the 9 potted off the cue ball before the 1 is a foul and comes back to the
// foot spot; under any ball the same shot is a legal pot and the 9 stays down.
TEST_F(GameTest, TheNinePottedOnAFoulComesBackToTheFootSpot) {
  auto balls = StraightPot(0.4, 0.4);
  balls[1].id = 9;
  balls.push_back(table::AtRest(1, 0.5, 0.3));
  const pot::PotPlan plan = Plan(balls, 9, "upper_right");
  ASSERT_EQ(plan.status, pot::PotStatus::kOk) << plan.reason;
  options_.player = std::make_shared<Scripted>(std::vector<physics::CueStroke>{plan.stroke});
  options_.execution = params::ExecutionNoise{};
  options_.shot_limit = 1;
  options_.choice.rules = rules::Rules::kNineBall;
  batch::ThreadPool pool(1);
  const GameRecord nine = PlayGame(table_, params_, balls, options_, pool);
  ASSERT_EQ(nine.shots.size(), 1u);
  EXPECT_EQ(nine.shots[0].potted, (std::vector<int>{9}));
  EXPECT_EQ(nine.shots[0].foul_reason, "first contact 9, not the lowest 1");
  EXPECT_FALSE(nine.summary.cleared);
  const auto spotted = std::find_if(nine.final_balls.begin(), nine.final_balls.end(),
                                    [](const table::SceneBall& b) { return b.id == 9; });
  ASSERT_NE(spotted, nine.final_balls.end());
  EXPECT_EQ(spotted->state.head<2>(), Eigen::Vector2d(0.75 * table_.length, 0.5 * table_.width));
  options_.choice.rules = rules::Rules::kAny;
  const GameRecord any = PlayGame(table_, params_, balls, options_, pool);
  EXPECT_FALSE(any.shots[0].foul);
  EXPECT_EQ(any.summary.balls_potted, 1);
  EXPECT_TRUE(std::none_of(any.final_balls.begin(), any.final_balls.end(),
                           [](const table::SceneBall& b) { return b.id == 9; }));
}

}  // namespace
}  // namespace billiard::game
