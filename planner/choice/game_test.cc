#include "planner/choice/game.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::choice {
namespace {

class GameTest : public ::testing::Test {
 protected:
  GameTest()
      : params_(params::LoadParameters("pool")),
        table_(table::BuildTable(params::LoadTableSpec("pool-9ft"))) {
    options_.choice.samples = 12;
    options_.choice.screen_samples = 6;
    options_.choice.finalists = 2;
    options_.choice.kinds = {pot::ShotKind::kDirect};
    options_.placements = 2;
    options_.shot_limit = 8;
  }
  table::SceneBall Ball(int id, double x, double y) const {
    table::SceneBall b;
    b.id = id;
    b.state.segment<2>(physics::kX) = Eigen::Vector2d(x, y);
    return b;
  }

  physics::ModelParameters params_;
  table::TableGeometry table_;
  GameOptions options_;
};

// Three open balls from ball in hand: cleared, and the summary adds up the shots.
TEST_F(GameTest, ClearsAnOpenTableAndCountsWhatHappened) {
  const std::vector<table::SceneBall> balls = {Ball(1, 1.9, 0.9), Ball(2, 0.8, 0.35),
                                               Ball(3, 1.3, 0.7)};
  options_.ball_in_hand = true;
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
}

TEST_F(GameTest, SameGameOnOneThreadOrTwo) {
  const auto balls = SeededNineBallLayout(table_, params_.ball.radius, 5);
  options_.choice.rules = Rules::kNineBall;
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
  options_.choice.rules = Rules::kNineBall;
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

}  // namespace
}  // namespace billiard::choice
