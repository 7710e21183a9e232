#include "sim/rules/ruleset.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/rack.h"

namespace billiard::rules {
namespace {


TEST(RulesetTest, ObjectBallsAreTheNumberedOnesAscending) {
  EXPECT_EQ(ObjectBalls({table::AtRest(5, 1, 1), table::AtRest(0, 2, 1), table::AtRest(2, 1, 0.5), table::AtRest(9, 0.5, 0.5)}),
            (std::vector<int>{2, 5, 9}));
  EXPECT_TRUE(ObjectBalls({table::AtRest(0, 1, 1)}).empty());
}

// The pocket games' fouls, each alone and in the order they are called.
TEST(RulesetTest, PocketGameFoulsInTheirOrder) {
  Shot shot;
  shot.first_contact = 1;
  EXPECT_EQ(PocketGameFoul(shot), "");
  shot.first_contact = -1;
  EXPECT_EQ(PocketGameFoul(shot), "no contact");
  shot.scratch = true;  // a scratch without contact is called a scratch
  EXPECT_EQ(PocketGameFoul(shot), "scratch");
  shot.struck = false;  // no stroke at all: nothing else happened
  EXPECT_EQ(PocketGameFoul(shot), "miscue");
}

TEST(RulesetTest, AFoulGivesBallInHandAndEndsTheVisit) {
  Shot shot;
  shot.potted = {3};
  const Judgement legal = PocketGameJudgement(shot, "");
  EXPECT_TRUE(legal.legal());
  EXPECT_FALSE(legal.turn_over);
  EXPECT_FALSE(legal.ball_in_hand);
  const Judgement foul = PocketGameJudgement(shot, "scratch");
  EXPECT_TRUE(foul.foul);
  EXPECT_EQ(foul.foul_reason, "scratch");
  EXPECT_TRUE(foul.turn_over);  // a ball potted on a foul does not keep the visit
  EXPECT_TRUE(foul.ball_in_hand);
  shot.potted.clear();
  const Judgement miss = PocketGameJudgement(shot, "");
  EXPECT_TRUE(miss.turn_over);  // a legal miss ends the visit, without ball in hand
  EXPECT_FALSE(miss.ball_in_hand);
}

class RespotTest : public ::testing::Test {
 protected:
  RespotTest()
      : radius_(params::LoadParameters("pool").ball.radius),
        table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  double radius_;
  table::TableGeometry table_;
};

TEST_F(RespotTest, OnItsSpotWhenFree) {
  const Eigen::Vector2d spot(0.75 * table_.length, 0.5 * table_.width);
  std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5)};
  PlaceRespotted(table_, radius_, {{9, spot, Eigen::Vector2d::UnitX()}}, 5e-3, 2e-3, &balls);
  ASSERT_EQ(balls.size(), 2u);
  EXPECT_EQ(balls.back().id, 9);
  EXPECT_EQ(balls.back().state.head<2>(), spot);
  EXPECT_EQ(balls.back().state.tail<5>().norm(), 0.0);  // at rest
}

// The spot taken: the first free place along the direction, a whole number of steps from it,
// clear of the ball on the spot.
TEST_F(RespotTest, BehindItsSpotWhenTaken) {
  const Eigen::Vector2d spot(0.75 * table_.length, 0.5 * table_.width);
  const double step = 1e-3, clearance = 2e-3;
  std::vector<table::SceneBall> balls = {table::AtRest(4, spot.x(), spot.y())};
  PlaceRespotted(table_, radius_, {{9, spot, Eigen::Vector2d::UnitX()}}, step, clearance, &balls);
  const Eigen::Vector2d at = balls.back().state.head<2>();
  EXPECT_EQ(at.y(), spot.y());  // on the long string
  const double moved = at.x() - spot.x();
  EXPECT_GE(moved, 2 * radius_ + clearance);
  EXPECT_LT(moved, 2 * radius_ + clearance + step + 1e-12);
  EXPECT_TRUE(table::FreePlace(table_, radius_, {balls.front()}, at, clearance));
}

// A run-out is one turn at the table from the first shot after the break: the breaker's, or
// after a dry break the incoming player's; a rack that needed a further visit, or was not
// cleared, is none.
TEST(RulesetTest, ARunOutIsOneTurnFromTheFirstShotAfterTheBreak) {
  EXPECT_TRUE(RunOut(true, 1, 1));    // break and run
  EXPECT_TRUE(RunOut(true, 2, 2));    // a dry break, then cleared by the next visit
  EXPECT_TRUE(RunOut(true, 1, 0));    // the 9 on the break
  EXPECT_FALSE(RunOut(true, 2, 1));   // the breaker missed after the break; a second visit
  EXPECT_FALSE(RunOut(true, 3, 2));   // a dry break, a miss, then cleared
  EXPECT_FALSE(RunOut(false, 1, 1));  // never cleared
}

}  // namespace
}  // namespace billiard::rules
