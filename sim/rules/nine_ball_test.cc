// Nine-ball judged case by case against the WPA Rules of Play's text (nine_ball.h).
#include "sim/rules/nine_ball.h"

#include <gtest/gtest.h>

#include "sim/params/table_specs.h"

namespace billiard::rules {
namespace {

class NineBallTest : public ::testing::Test {
 protected:
  NineBallTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  // A shot whose lowest ball on the table is `lowest`, first meeting `first` (and driving it to
  // a rail), potting `potted` and leaving `left` object balls.
  static Shot Played(int lowest, int first, std::vector<int> potted, int left) {
    Shot s;
    s.constraints.legal_targets = {lowest};
    s.first_contact = first;
    if (first >= 0) s.to_rail_after_contact = {first};
    s.potted = std::move(potted);
    s.object_balls_left = left;
    return s;
  }
  static table::SceneBall Ball(int id) {
    table::SceneBall b;
    b.id = id;
    return b;
  }
  table::TableGeometry table_;
  NineBall rules_;
};

// "On each shot the first ball the cue ball contacts must be the lowest-numbered ball on the
// table": the lowest is the only target.
TEST_F(NineBallTest, TheLowestBallIsTheOnlyTarget) {
  EXPECT_EQ(rules_.LegalTargets({Ball(0), Ball(7), Ball(4), Ball(9)}), (std::vector<int>{4}));
  EXPECT_TRUE(rules_.LegalTargets({Ball(0)}).empty());
}

// "... but the balls need not be pocketed in order": the 2 hit first potting the 6 is legal,
// and the shooter stays at the table.
TEST_F(NineBallTest, ALegalPotOfAnotherBallKeepsTheVisit) {
  const Judgement j = rules_.Judge(table_, Played(2, 2, {6}, 6));
  EXPECT_TRUE(j.legal());
  EXPECT_FALSE(j.turn_over);
  EXPECT_FALSE(j.ball_in_hand);
  EXPECT_FALSE(j.rack_over);
  EXPECT_TRUE(j.respots.empty());
}

// A legal shot that pots nothing: the turn passes, the balls as they lie (no ball in hand).
TEST_F(NineBallTest, ALegalMissEndsTheVisitWithoutBallInHand) {
  const Judgement j = rules_.Judge(table_, Played(2, 2, {}, 7));
  EXPECT_TRUE(j.legal());
  EXPECT_TRUE(j.turn_over);
  EXPECT_FALSE(j.ball_in_hand);
}

// Wrong Ball First: a foul, named with the ball met and the lowest; the incoming player has
// the cue ball in hand.
TEST_F(NineBallTest, WrongBallFirstIsAFoul) {
  const Judgement j = rules_.Judge(table_, Played(2, 3, {3}, 6));
  EXPECT_TRUE(j.foul);
  EXPECT_EQ(j.foul_reason, "first contact 3, not the lowest 2");
  EXPECT_TRUE(j.turn_over);
  EXPECT_TRUE(j.ball_in_hand);
}

// "The breaker must strike the one ball first": the 3 met before the 1 is a foul on the break
// too.
TEST_F(NineBallTest, TheBreakMustMeetTheOneFirst) {
  Shot s = Played(1, 3, {5}, 8);
  s.break_shot = true;
  EXPECT_EQ(rules_.Judge(table_, s).foul_reason, "first contact 3, not the lowest 1");
  s.first_contact = 1;
  EXPECT_TRUE(rules_.Judge(table_, s).legal());
}

// A legal break pots a ball or drives four numbered balls to the rail; the cue ball's own rail
// does not count. Three numbered balls and the cue ball is a foul, with ball in hand.
TEST_F(NineBallTest, ALegalBreakPotsOrDrivesFourBallsToTheRail) {
  Shot s = Played(1, 1, {}, 9);
  s.break_shot = true;
  s.to_rail_after_contact = {2, 3, 5, 7};
  const Judgement four = rules_.Judge(table_, s);
  EXPECT_TRUE(four.legal());
  EXPECT_TRUE(four.turn_over);  // nothing potted: the other player comes to the table
  s.to_rail_after_contact = {0, 2, 3, 5};
  const Judgement three = rules_.Judge(table_, s);
  EXPECT_EQ(three.foul_reason, "break: no ball potted and 3 object balls to a rail, not 4");
  EXPECT_TRUE(three.ball_in_hand);
  s.to_rail_after_contact.clear();
  s.potted = {6};
  const Judgement potted = rules_.Judge(table_, s);
  EXPECT_TRUE(potted.legal());
  EXPECT_FALSE(potted.turn_over);
}

// The 9 potted on a legal break wins the rack.
TEST_F(NineBallTest, TheNineOnALegalBreakWins) {
  Shot s = Played(1, 1, {9}, 8);
  s.break_shot = true;
  const Judgement j = rules_.Judge(table_, s);
  EXPECT_TRUE(j.rack_over);
  EXPECT_TRUE(j.shooter_wins);
  EXPECT_EQ(j.rack_reason, "9 potted legally");
}

// No Rail after Contact: the lowest met, nothing potted, no ball to a rail after; a ball to a
// rail (the cue ball's own counts) makes the shot legal.
TEST_F(NineBallTest, NoRailAfterContactIsAFoul) {
  Shot s = Played(2, 2, {}, 7);
  s.to_rail_after_contact.clear();
  const Judgement j = rules_.Judge(table_, s);
  EXPECT_EQ(j.foul_reason, "no rail after contact");
  EXPECT_TRUE(j.ball_in_hand);
  s.to_rail_after_contact = {0};
  EXPECT_TRUE(rules_.Judge(table_, s).legal());
  s.to_rail_after_contact.clear();
  s.potted = {2};  // a ball potted needs no rail
  EXPECT_TRUE(rules_.Judge(table_, s).legal());
}

// Push Out: no ball need be met and no rail reached; the table passes with the option to hand it
// back; a 9 potted is spotted and wins nothing; a scratch is still a foul.
TEST_F(NineBallTest, APushOutNeedsNoContactAndOffersTheTable) {
  Shot s = Played(1, -1, {}, 8);
  s.push_out = true;
  s.constraints.push_out_allowed = true;
  const Judgement j = rules_.Judge(table_, s);
  EXPECT_TRUE(j.legal());
  EXPECT_TRUE(j.turn_over);
  EXPECT_TRUE(j.opponent_may_pass);
  EXPECT_FALSE(j.ball_in_hand);
  s.potted = {9};
  const Judgement nine = rules_.Judge(table_, s);
  EXPECT_FALSE(nine.rack_over);
  ASSERT_EQ(nine.respots.size(), 1u);
  EXPECT_EQ(nine.respots[0].ball, NineBall::kNine);
  s.scratch = true;
  const Judgement scratch = rules_.Judge(table_, s);
  EXPECT_EQ(scratch.foul_reason, "scratch");
  EXPECT_FALSE(scratch.opponent_may_pass);
  EXPECT_TRUE(scratch.ball_in_hand);
}

// A push-out is the shot after the break's alone: declared elsewhere it is a foul.
TEST_F(NineBallTest, APushOutNotAllowedIsAFoul) {
  Shot s = Played(1, -1, {}, 8);
  s.push_out = true;
  EXPECT_EQ(rules_.Judge(table_, s).foul_reason, "push-out not allowed");
}

// Cue Ball Scratch, no contact, a miscue: fouls, called in that order of precedence (a scratch
// that met the wrong ball first is called a scratch).
TEST_F(NineBallTest, ScratchNoContactAndMiscueAreFouls) {
  Shot scratch = Played(2, 5, {}, 7);
  scratch.scratch = true;
  EXPECT_EQ(rules_.Judge(table_, scratch).foul_reason, "scratch");
  EXPECT_EQ(rules_.Judge(table_, Played(2, -1, {}, 7)).foul_reason, "no contact");
  Shot miscue = Played(2, -1, {}, 7);
  miscue.struck = false;
  const Judgement j = rules_.Judge(table_, miscue);
  EXPECT_EQ(j.foul_reason, "miscue");
  EXPECT_TRUE(j.ball_in_hand);
}

// "The game is won by pocketing the 9 on a legal shot": a combination off the lowest wins,
// balls left or not.
TEST_F(NineBallTest, TheNinePottedLegallyWinsTheRack) {
  const Judgement j = rules_.Judge(table_, Played(3, 3, {9}, 5));
  EXPECT_TRUE(j.legal());
  EXPECT_TRUE(j.rack_over);
  EXPECT_TRUE(j.shooter_wins);
  EXPECT_TRUE(j.respots.empty());
}

// The 9 potted on a foul is spotted on the foot spot (toward the foot rail when taken), and
// the rack goes on, even when it was the last ball.
TEST_F(NineBallTest, TheNinePottedOnAFoulIsRespotted) {
  for (int left : {4, 0}) {
    Shot s = Played(3, 5, {9}, left);
    const Judgement j = rules_.Judge(table_, s);
    EXPECT_EQ(j.foul_reason, "first contact 5, not the lowest 3");
    ASSERT_EQ(j.respots.size(), 1u);
    EXPECT_EQ(j.respots[0].ball, NineBall::kNine);
    EXPECT_EQ(j.respots[0].spot, Eigen::Vector2d(0.75 * table_.length, 0.5 * table_.width));
    EXPECT_EQ(j.respots[0].toward, Eigen::Vector2d(1, 0));  // x = length is the foot rail
    EXPECT_FALSE(j.rack_over) << left;
  }
  // Another ball potted on a foul stays down.
  Shot other = Played(3, 5, {4}, 4);
  EXPECT_TRUE(rules_.Judge(table_, other).respots.empty());
}

// A rack without the 9 (a drill's) is over when its last ball drops legally; the lookahead
// sees a table without the 9 as one whose rack is over.
TEST_F(NineBallTest, ARackWithoutTheNineIsOverWhenEmpty) {
  EXPECT_TRUE(rules_.Judge(table_, Played(4, 4, {4}, 0)).rack_over);
  EXPECT_FALSE(rules_.Judge(table_, Played(4, 4, {4}, 1)).rack_over);
  EXPECT_TRUE(rules_.RackOver({Ball(0), Ball(4)}));
  EXPECT_FALSE(rules_.RackOver({Ball(0), Ball(4), Ball(9)}));
  EXPECT_TRUE(rules_.RackOver({Ball(0)}));
}

TEST_F(NineBallTest, TheFootSpotIsTheMiddleOfTheFootHalf) {
  const Eigen::Vector2d spot = FootSpot(table_);
  EXPECT_DOUBLE_EQ(spot.x() - 0.5 * table_.length, table_.length - spot.x());
  EXPECT_DOUBLE_EQ(spot.y(), table_.width - spot.y());
}

}  // namespace
}  // namespace billiard::rules
