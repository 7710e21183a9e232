// Eight-ball judged case by case against the computational pool's rules (eight_ball.h:
// FastFiz's EightBallState, the World Standardized Rules where it is silent).
#include "sim/rules/eight_ball.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"

namespace billiard::rules {
namespace {

class EightBallTest : public ::testing::Test {
 protected:
  EightBallTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  // A shot under `rules` on a table holding `on_table`, first meeting `first` (driven to a
  // rail), calling `called` in the corner "tr", potting `potted` there.
  static Shot Played(const EightBall& rules, std::vector<int> on_table, int first, int called,
                     std::vector<int> potted) {
    std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5)};
    for (int id : on_table) balls.push_back(table::AtRest(id, 1.0, 0.5));
    Shot s;
    s.constraints.legal_targets = rules.LegalTargets(balls);
    s.constraints.call_required = true;
    s.first_contact = first;
    s.to_rail_after_contact = {first};
    s.call = {called, "tr"};
    s.pockets.assign(potted.size(), "tr");
    s.potted = std::move(potted);
    s.object_balls_left = static_cast<int>(on_table.size() - s.potted.size());
    return s;
  }
  table::TableGeometry table_;
  const EightBall open_{Group::kOpen};
  const EightBall solids_{Group::kSolids};
  const EightBall stripes_{Group::kStripes};
};

TEST_F(EightBallTest, TheGroupsAndTheirNames) {
  EXPECT_EQ(GroupOf(1), Group::kSolids);
  EXPECT_EQ(GroupOf(7), Group::kSolids);
  EXPECT_EQ(GroupOf(8), Group::kOpen);
  EXPECT_EQ(GroupOf(9), Group::kStripes);
  EXPECT_EQ(GroupOf(15), Group::kStripes);
  EXPECT_EQ(OtherGroup(Group::kSolids), Group::kStripes);
  EXPECT_STREQ(open_.Name(), "eight-ball");
  EXPECT_STREQ(solids_.Name(), "eight-ball-solids");
  EXPECT_STREQ(stripes_.Name(), "eight-ball-stripes");
  EXPECT_TRUE(open_.CallsShots());
}

// Open: every ball but the 8; a group: its balls; cleared: the 8 alone.
TEST_F(EightBallTest, LegalTargetsFollowTheGroup) {
  std::vector<table::SceneBall> balls = {table::AtRest(0, 0.5, 0.5)};
  for (int id : {3, 8, 12}) balls.push_back(table::AtRest(id, 1.0, 0.2 * id));
  EXPECT_EQ(open_.LegalTargets(balls), (std::vector<int>{3, 12}));
  EXPECT_EQ(solids_.LegalTargets(balls), (std::vector<int>{3}));
  EXPECT_EQ(stripes_.LegalTargets(balls), (std::vector<int>{12}));
  balls.erase(balls.begin() + 1);  // the 3 gone: the solids cleared
  EXPECT_EQ(solids_.LegalTargets(balls), (std::vector<int>{8}));
  EXPECT_FALSE(solids_.RackOver(balls));
  balls.erase(balls.begin() + 1);  // the 8 gone
  EXPECT_TRUE(solids_.RackOver(balls));
}

// A called ball potted as called keeps the visit; on an open table it gives its group.
TEST_F(EightBallTest, ACalledPotKeepsTheVisitAndTakesTheGroup) {
  const Judgement j = open_.Judge(table_, Played(open_, {3, 8, 12}, 12, 12, {12}));
  EXPECT_TRUE(j.legal());
  EXPECT_FALSE(j.turn_over);
  EXPECT_EQ(j.group_ball, 12);
  const Judgement again = stripes_.Judge(table_, Played(stripes_, {3, 8, 12, 13}, 12, 12, {12}));
  EXPECT_FALSE(again.turn_over);
  EXPECT_EQ(again.group_ball, -1);  // a group is taken once
}

// A ball potted but not as called (another ball, or another pocket) ends the visit, no foul.
TEST_F(EightBallTest, APotNotAsCalledEndsTheVisit) {
  const Judgement other = solids_.Judge(table_, Played(solids_, {2, 3, 8, 12}, 2, 2, {3}));
  EXPECT_TRUE(other.legal());
  EXPECT_TRUE(other.turn_over);
  Shot pocket = Played(solids_, {2, 3, 8, 12}, 2, 2, {2});
  pocket.pockets = {"bl"};
  EXPECT_TRUE(solids_.Judge(table_, pocket).turn_over);
  EXPECT_EQ(open_.Judge(table_, pocket).group_ball, -1);
}

// The first ball met must be of the group; on an open table any but the 8.
TEST_F(EightBallTest, WrongFirstContactIsAFoul) {
  const Judgement stripe = solids_.Judge(table_, Played(solids_, {2, 8, 12}, 12, 2, {}));
  EXPECT_EQ(stripe.foul_reason, "first contact 12, not a solid");
  EXPECT_TRUE(stripe.ball_in_hand);
  EXPECT_EQ(open_.Judge(table_, Played(open_, {2, 8, 12}, 8, 2, {})).foul_reason,
            "first contact 8, not a solid or a stripe");
  EXPECT_EQ(stripes_.Judge(table_, Played(stripes_, {2, 8}, 2, 8, {})).foul_reason,
            "first contact 2, not the 8");
}

// After the contact a called pot or a rail; a pot not called does not save it (FastFiz).
TEST_F(EightBallTest, NoRailAfterContactIsAFoul) {
  Shot s = Played(solids_, {2, 3, 8}, 2, 2, {3});
  s.to_rail_after_contact.clear();
  EXPECT_EQ(solids_.Judge(table_, s).foul_reason, "no rail after contact");
  s.potted = {2};
  EXPECT_TRUE(solids_.Judge(table_, s).legal());
}

TEST_F(EightBallTest, TheFoulsOfThePocketGames) {
  Shot s = Played(solids_, {2, 8}, 2, 2, {2});
  s.scratch = true;
  const Judgement j = solids_.Judge(table_, s);
  EXPECT_EQ(j.foul_reason, "scratch");
  EXPECT_TRUE(j.turn_over);  // a called pot on a foul counts for nothing
  EXPECT_TRUE(j.ball_in_hand);
  EXPECT_EQ(solids_.Judge(table_, Played(solids_, {2, 8}, -1, 2, {})).foul_reason, "no contact");
}

// The 8 potted as called with the group cleared wins; early, not as called, or on a foul loses.
TEST_F(EightBallTest, TheEightWinsLastAndLosesOtherwise) {
  const Judgement win = solids_.Judge(table_, Played(solids_, {8, 12}, 8, 8, {8}));
  EXPECT_TRUE(win.rack_over);
  EXPECT_TRUE(win.shooter_wins);
  EXPECT_EQ(win.rack_reason, "8 potted as called");
  const Judgement early = solids_.Judge(table_, Played(solids_, {2, 8}, 2, 2, {2, 8}));
  EXPECT_TRUE(early.rack_over);
  EXPECT_FALSE(early.shooter_wins);
  EXPECT_EQ(early.rack_reason, "8 potted before its group was cleared");
  Shot pocket = Played(solids_, {8}, 8, 8, {8});
  pocket.call.pocket = "bl";
  EXPECT_EQ(solids_.Judge(table_, pocket).rack_reason, "8 potted, not as called");
  Shot scratch = Played(solids_, {8}, 8, 8, {8});
  scratch.scratch = true;
  const Judgement foul = solids_.Judge(table_, scratch);
  EXPECT_FALSE(foul.shooter_wins);
  EXPECT_EQ(foul.rack_reason, "8 potted on a foul (scratch)");
}

// The break: a pot or four object balls to a rail; the 8 on it is spotted, not a loss.
TEST_F(EightBallTest, TheBreak) {
  Shot s = Played(open_, {1, 2, 3, 8, 9, 10, 11}, 1, -1, {});
  s.break_shot = true;
  s.to_rail_after_contact = {0, 1, 2, 9};
  EXPECT_EQ(open_.Judge(table_, s).foul_reason,
            "break: no ball potted and 3 object balls to a rail, not 4");
  s.to_rail_after_contact = {1, 2, 9, 10};
  EXPECT_TRUE(open_.Judge(table_, s).legal());
  s.potted = {8};
  s.pockets = {"tr"};
  const Judgement eight = open_.Judge(table_, s);
  EXPECT_TRUE(eight.legal());
  EXPECT_FALSE(eight.rack_over);
  ASSERT_EQ(eight.respots.size(), 1u);
  EXPECT_EQ(eight.respots[0].ball, EightBall::kEight);
  EXPECT_EQ(eight.group_ball, -1);  // the table stays open
}

}  // namespace
}  // namespace billiard::rules
