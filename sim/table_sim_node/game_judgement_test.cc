#include "sim/table_sim_node/game_judgement.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"
#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {
namespace {

constexpr double kRadius = 0.028575;

table::TableGeometry Pool() { return table::BuildTable(params::LoadTableSpec("pool-9ft")); }

// A shot that is not the break, the 2 the lowest ball, its call dropped.
GameShotFacts Shot(int first_contact, std::vector<int> potted, bool scratch = false) {
  GameShotFacts shot;
  shot.lowest = 2;
  shot.called_potted = !potted.empty();
  shot.first_contact = first_contact;
  shot.potted = std::move(potted);
  shot.scratch = scratch;
  return shot;
}

GameVerdict Judged(const GameShotFacts& shot, const std::vector<table::SceneBall>& left = {}) {
  return JudgeNineBallShot(shot, Pool(), kRadius, left);
}

TEST(JudgeNineBallShot, TheLowestBallFirstIsLegalAndItsCalledPotCounts) {
  const GameVerdict verdict = Judged(Shot(2, {4}));
  EXPECT_EQ(verdict.foul_reason, "");
  EXPECT_TRUE(verdict.called_potted);
  EXPECT_FALSE(verdict.nine_legal);
  EXPECT_FALSE(verdict.nine_spot);
}

TEST(JudgeNineBallShot, AScratchIsAFoulWhateverElseHappened) {
  const GameVerdict verdict = Judged(Shot(-1, {2}, true));
  EXPECT_EQ(verdict.foul_reason, "scratch");
  EXPECT_FALSE(verdict.called_potted);
  EXPECT_EQ(Judged(Shot(2, {}, true)).foul_reason, "scratch");
}

TEST(JudgeNineBallShot, MeetingNoBallIsAFoul) {
  EXPECT_EQ(Judged(Shot(-1, {})).foul_reason, "no contact");
}

TEST(JudgeNineBallShot, MeetingAnotherBallThanTheLowestFirstIsAFoul) {
  const GameVerdict verdict = Judged(Shot(5, {2}));
  EXPECT_EQ(verdict.foul_reason, "first contact 5, not the lowest 2");
  EXPECT_FALSE(verdict.called_potted);
}

// The break may meet any ball first, but not none, and not scratch.
TEST(JudgeNineBallShot, TheBreakMayMeetAnyBallFirst) {
  GameShotFacts brk = Shot(5, {3, 7});
  brk.break_shot = true;
  EXPECT_EQ(Judged(brk).foul_reason, "");
  brk.first_contact = -1;
  EXPECT_EQ(Judged(brk).foul_reason, "no contact");
  brk.first_contact = 5;
  brk.scratch = true;
  EXPECT_EQ(Judged(brk).foul_reason, "scratch");
}

TEST(JudgeNineBallShot, TheNineDroppedOnALegalShotWinsTheRack) {
  const GameVerdict verdict = Judged(Shot(2, {2, 9}));
  EXPECT_TRUE(verdict.nine_legal);
  EXPECT_FALSE(verdict.nine_spot);
}

// The 9 dropped on a foul comes back on the foot spot (x = 3/4 length, the middle of the
// width), or behind a ball there toward the foot rail, clear of it.
TEST(JudgeNineBallShot, TheNineDroppedOnAFoulIsRespottedOnTheFootSpot) {
  const table::TableGeometry table = Pool();
  const Eigen::Vector2d foot_spot(0.75 * table.length, 0.5 * table.width);
  const GameVerdict free = Judged(Shot(5, {9}));
  EXPECT_FALSE(free.nine_legal);
  ASSERT_TRUE(free.nine_spot);
  EXPECT_EQ(*free.nine_spot, foot_spot);

  table::SceneBall on_spot{3, physics::BallState::Zero()};
  on_spot.state.head<2>() = foot_spot;
  const GameVerdict blocked = Judged(Shot(-1, {9}, true), {on_spot});
  ASSERT_TRUE(blocked.nine_spot);
  EXPECT_GT(blocked.nine_spot->x(), foot_spot.x());
  EXPECT_EQ(blocked.nine_spot->y(), foot_spot.y());
  EXPECT_GE(blocked.nine_spot->x() - foot_spot.x(), 2.0 * kRadius + kPlacementClearance);
}

}  // namespace
}  // namespace billiard::table_sim_node
