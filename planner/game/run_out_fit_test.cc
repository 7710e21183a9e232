#include "planner/game/run_out_fit.h"

#include <gtest/gtest.h>

#include <vector>

#include "planner/game/match_summary.h"

namespace billiard::game {
namespace {

struct Shot {
  int player;
  bool foul = false;
  double attempt_win = -1.0;  // the weighed decision's estimates; -1 not weighed
  double safety_win = -1.0;
  bool safety = false;
};

// A rack of `shots` (the first the break), won by `winner` (-1: undecided), as its log line.
nlohmann::json Rack(const std::vector<Shot>& shots, int winner) {
  RackResult rack;
  rack.winner = winner;
  for (std::size_t i = 0; i < shots.size(); ++i) {
    ShotRecord rec;
    rec.number = static_cast<int>(i);
    rec.player = shots[i].player;
    rec.break_shot = i == 0;
    rec.foul = shots[i].foul;
    rec.attempt_win = shots[i].attempt_win;
    rec.safety_win = shots[i].safety_win;
    rec.safety = shots[i].safety;
    rack.shots.push_back(rec);
  }
  return RackJson(rack);
}

// Player 0 breaks and pots, then pots twice and misses (the shot after the break not counted);
// player 1 arrives and misses; player 0 arrives and fouls; player 1 with ball in hand (not an
// arrival after a miss) runs out.
TEST(RunOutFitTest, CountsContinuingAndArrivingShotsByWhoShootsNext) {
  const nlohmann::json rack =
      Rack({{0}, {0}, {0}, {0}, {1}, {0, true}, {1}, {1}}, /*winner=*/1);
  RunOutCounts zero;
  CountRunOut(rack, 0, &zero);
  // Shot 1 follows the break: not counted. Shots 2 and 3 continue (2 kept, 3 missed); shot 5
  // arrives after 1's miss and fouls (not kept).
  EXPECT_EQ(zero.continuing, 2);
  EXPECT_EQ(zero.continuing_kept, 1);
  EXPECT_EQ(zero.arriving, 1);
  EXPECT_EQ(zero.arriving_kept, 0);
  RunOutCounts one;
  CountRunOut(rack, 1, &one);
  // Shot 4 arrives after 0's miss and misses; shot 6 follows a foul (ball in hand): not counted;
  // shot 7, the last, continues and won the rack.
  EXPECT_EQ(one.arriving, 1);
  EXPECT_EQ(one.arriving_kept, 0);
  EXPECT_EQ(one.continuing, 1);
  EXPECT_EQ(one.continuing_kept, 1);
}

TEST(RunOutFitTest, TheLastShotOfAnUndecidedRackIsNotCounted) {
  RunOutCounts counts;
  CountRunOut(Rack({{0}, {1}, {0}}, -1), 0, &counts);
  EXPECT_EQ(counts.arriving, 0);
  CountRunOut(Rack({{0}, {1}, {0}}, 0), 0, &counts);
  EXPECT_EQ(counts.arriving, 1);
  EXPECT_EQ(counts.arriving_kept, 1);
}

// Player 0 weighs two decisions in a rack it wins (a safety played at 0.6, an attempt at 0.7)
// and one in a rack it loses (a safety at 0.5); a shot weighed by nothing is not counted.
TEST(RunOutFitTest, SumsTheWeighedDecisionsEstimatesAgainstTheRacksWon) {
  RunOutCounts counts;
  CountRunOut(Rack({{1}, {0, false, 0.4, 0.6, true}, {1}, {0, false, 0.7, 0.3}, {0}}, 0), 0,
              &counts);
  CountRunOut(Rack({{0}, {0, false, 0.45, 0.5, true}, {1}, {0}, {1}}, 1), 0, &counts);
  EXPECT_EQ(counts.safeties.count, 2);
  EXPECT_DOUBLE_EQ(counts.safeties.estimated, 1.1);
  EXPECT_EQ(counts.safeties.won, 1);
  EXPECT_EQ(counts.attempts.count, 1);
  EXPECT_DOUBLE_EQ(counts.attempts.estimated, 0.7);
  EXPECT_EQ(counts.attempts.won, 1);
}

}  // namespace
}  // namespace billiard::game
