#include "planner/game/match_report.h"

#include <gtest/gtest.h>

namespace billiard::game {
namespace {

// A shot by `player`; a break when `break_shot`.
ShotRecord Shot(int player, std::vector<int> potted, bool foul = false,
                const std::string& reason = "", bool break_shot = false) {
  ShotRecord s;
  s.player = player;
  s.potted = std::move(potted);
  s.foul = foul;
  s.foul_reason = reason;
  s.break_shot = break_shot;
  return s;
}

RackResult Rack(int breaker, int winner, std::vector<ShotRecord> shots) {
  RackResult r;
  r.breaker = breaker;
  r.winner = winner;
  r.shots = std::move(shots);
  return r;
}

// Four racks whose figures are counted by hand: a break-and-run by 0; a dry break by 1 after
// which 0 runs out; a legal break by 0 that pots, then 0 misses and 1 runs out (1's first
// visit); a break by 1 that scratches (no legal break: no chance for either).
MatchRecord FourRacks() {
  MatchRecord m;
  m.racks.push_back(Rack(0, 0, {Shot(0, {3}, false, "", true), Shot(0, {1}), Shot(0, {9})}));
  m.racks.push_back(Rack(1, 0, {Shot(1, {}, false, "", true), Shot(0, {1}), Shot(0, {9})}));
  m.racks.push_back(Rack(0, 1, {Shot(0, {2}, false, "", true), Shot(0, {}), Shot(1, {1}),
                                Shot(1, {9})}));
  m.racks.push_back(Rack(1, 0, {Shot(1, {4}, true, "scratch", true), Shot(0, {1}), Shot(1, {}),
                                Shot(0, {9})}));
  return m;
}

TEST(MatchReportTest, BreaksAreTheRacksFirstShots) {
  const MatchBreaks b = BreaksOf(FourRacks());
  EXPECT_EQ(b.racks, 4);
  EXPECT_EQ(b.legal, 3);
  EXPECT_EQ(b.potted, 3);
  EXPECT_EQ(b.kept, 2);
  EXPECT_EQ(b.scratches, 1);
}

TEST(MatchReportTest, OneVisitClearsCountTheFirstVisitAfterALegalBreak) {
  const std::array<OneVisitClears, 2> c = OneVisitClearsOf(FourRacks());
  // Player 0: rack 1 (break and run), rack 2 (ran out after the dry break), rack 3 (its first
  // visit, the break's continuation, missed): 3 chances, 2 clears.
  EXPECT_EQ(c[0].chances, 3);
  EXPECT_EQ(c[0].clears, 2);
  // Player 1: rack 2 (its dry break is no visit after the break; it never shot again) is no
  // chance; rack 3 it cleared: 1 chance, 1 clear.
  EXPECT_EQ(c[1].chances, 1);
  EXPECT_EQ(c[1].clears, 1);
}

}  // namespace
}  // namespace billiard::game
