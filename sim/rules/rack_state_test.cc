// A rack between two players: whose turn, the fouls in a row, the groups, the push-out's option,
// and who won, each followed shot by shot through constructed shots.
#include "sim/rules/rack_state.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"

namespace billiard::rules {
namespace {

class RackStateTest : public ::testing::Test {
 protected:
  RackStateTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  std::vector<table::SceneBall> Balls(std::vector<int> ids) const {
    std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5)};
    for (int id : ids) balls.push_back(table::AtRest(id, 1.0, 0.1 * id));
    return balls;
  }
  // The next shot of `rack` on `ids`, meeting the first legal ball and driving it to a rail,
  // potting `potted` in "tr" (the call when one is due).
  Shot Next(const RackState& rack, std::vector<int> ids, std::vector<int> potted) const {
    Shot s;
    s.constraints = NextConstraints(rack, Balls(ids));
    s.break_shot = rack.shots == 0;
    s.first_contact = s.constraints.legal_targets.front();
    s.to_rail_after_contact = {0, 1, 2, 3, 4};
    if (s.constraints.call_required && !potted.empty()) s.call = {potted.front(), "tr"};
    s.pockets.assign(potted.size(), "tr");
    s.potted = std::move(potted);
    s.object_balls_left = static_cast<int>(ids.size() - s.potted.size());
    return s;
  }
  // A foul: the shot with no ball met.
  Shot Foul(const RackState& rack, std::vector<int> ids) const {
    Shot s = Next(rack, std::move(ids), {});
    s.first_contact = -1;
    return s;
  }
  table::TableGeometry table_;
};

TEST_F(RackStateTest, TheBreakerBreaksAndAMissPassesTheTable) {
  RackState rack = NewRack(Rules::kNineBall, 1);
  EXPECT_EQ(rack.shooter, 1);
  const Constraints brk = NextConstraints(rack, Balls({1, 2, 9}));
  EXPECT_FALSE(brk.push_out_allowed);
  EXPECT_FALSE(brk.call_required);
  EXPECT_EQ(brk.legal_targets, (std::vector<int>{1}));
  Referee(table_, Next(rack, {1, 2, 9}, {2}), &rack);  // a ball potted: the breaker goes on
  EXPECT_EQ(rack.shooter, 1);
  EXPECT_TRUE(NextConstraints(rack, Balls({1, 9})).push_out_allowed);  // the shot after it
  Referee(table_, Next(rack, {1, 9}, {}), &rack);
  EXPECT_EQ(rack.shooter, 0);
  EXPECT_FALSE(rack.ball_in_hand);
  EXPECT_FALSE(NextConstraints(rack, Balls({1, 9})).push_out_allowed);
}

TEST_F(RackStateTest, AFoulGivesTheOtherPlayerBallInHand) {
  RackState rack = NewRack(Rules::kNineBall, 0);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);
  const Judgement j = Referee(table_, Foul(rack, {1, 2, 9}), &rack);
  EXPECT_EQ(j.foul_reason, "no contact");
  EXPECT_EQ(rack.shooter, 0);
  EXPECT_TRUE(rack.ball_in_hand);
  EXPECT_TRUE(NextConstraints(rack, Balls({1, 2, 9})).ball_in_hand);
}

// Three fouls in a row by one player, the other's legal misses between, lose the rack; a legal
// shot between starts the count again.
TEST_F(RackStateTest, ThreeFoulsInARowLoseNineBall) {
  RackState rack = NewRack(Rules::kNineBall, 1);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);  // player 1 breaks, nothing potted
  auto foul_then_miss = [&] {
    Referee(table_, Foul(rack, {1, 2, 9}), &rack);  // player 0 fouls
    if (!rack.over) Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);  // player 1 misses
  };
  foul_then_miss();
  foul_then_miss();
  EXPECT_EQ(rack.fouls_in_a_row[0], 2);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);  // player 0 legal: the count cleared
  EXPECT_EQ(rack.fouls_in_a_row[0], 0);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);
  for (int i = 0; i < 3; ++i) foul_then_miss();
  EXPECT_TRUE(rack.over);
  EXPECT_EQ(rack.winner, 1);
  EXPECT_EQ(rack.reason, "3 fouls in a row");
}

// Eight-ball has no such rule: fouls alone never end its rack.
TEST_F(RackStateTest, FoulsDoNotLoseEightBall) {
  RackState rack = NewRack(Rules::kEightBall, 0);
  Referee(table_, Next(rack, {1, 8, 9}, {}), &rack);
  for (int i = 0; i < 6; ++i) Referee(table_, Foul(rack, {1, 8, 9}), &rack);
  EXPECT_FALSE(rack.over);
}

TEST_F(RackStateTest, TheNineWinsForTheShooter) {
  RackState rack = NewRack(Rules::kNineBall, 0);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);
  Referee(table_, Next(rack, {1, 2, 9}, {9}), &rack);  // player 1, off the 1
  EXPECT_TRUE(rack.over);
  EXPECT_EQ(rack.winner, 1);
  EXPECT_EQ(rack.reason, "9 potted legally");
}

// The first called pot on the open table gives the shooter its group and the other player the
// other; the call is due after the break alone.
TEST_F(RackStateTest, EightBallGroupsAreTakenByTheFirstCalledPot) {
  RackState rack = NewRack(Rules::kEightBall, 0);
  EXPECT_FALSE(NextConstraints(rack, Balls({1, 8, 9, 10})).call_required);
  Referee(table_, Next(rack, {1, 8, 9, 10}, {}), &rack);
  const Constraints open = NextConstraints(rack, Balls({1, 8, 9, 10}));
  EXPECT_TRUE(open.call_required);
  EXPECT_EQ(open.legal_targets, (std::vector<int>{1, 9, 10}));
  Shot stripe = Next(rack, {1, 8, 9, 10}, {9});
  stripe.first_contact = 9;
  Referee(table_, stripe, &rack);  // player 1 pots the 9 as called
  EXPECT_EQ(rack.shooter, 1);
  EXPECT_EQ(rack.rules[1], Rules::kEightBallStripes);
  EXPECT_EQ(rack.rules[0], Rules::kEightBallSolids);
  EXPECT_EQ(NextConstraints(rack, Balls({1, 8, 10})).legal_targets, (std::vector<int>{10}));
  Referee(table_, Next(rack, {1, 8, 10}, {}), &rack);
  EXPECT_EQ(NextConstraints(rack, Balls({1, 8, 10})).legal_targets, (std::vector<int>{1}));
}

TEST_F(RackStateTest, TheEightEarlyLosesForTheShooter) {
  RackState rack = NewRack(Rules::kEightBall, 0);
  Referee(table_, Next(rack, {1, 8, 9}, {}), &rack);
  Shot early = Next(rack, {1, 8, 9}, {1, 8});
  Referee(table_, early, &rack);
  EXPECT_TRUE(rack.over);
  EXPECT_EQ(rack.winner, 0);
  EXPECT_EQ(rack.reason, "8 potted before its group was cleared");
}

// After a legal push-out the incoming player may take the table or hand it back.
TEST_F(RackStateTest, APushOutMayBeHandedBack) {
  RackState rack = NewRack(Rules::kNineBall, 0);
  Referee(table_, Next(rack, {1, 2, 9}, {}), &rack);  // player 1 comes to the table
  Shot push = Foul(rack, {1, 2, 9});
  push.push_out = true;
  const Judgement j = Referee(table_, push, &rack);
  EXPECT_TRUE(j.legal());
  EXPECT_EQ(rack.shooter, 0);
  EXPECT_TRUE(rack.may_pass);
  PassBack(&rack);
  EXPECT_EQ(rack.shooter, 1);
  EXPECT_FALSE(rack.may_pass);
  EXPECT_EQ(rack.fouls_in_a_row[1], 0);
}

}  // namespace
}  // namespace billiard::rules
