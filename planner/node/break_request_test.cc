// MODE_BREAK through the node: the break of the game the request names, on the rack the
// estimator sees, against its geometry (the cue ball on the head string at the stored break's
// offset, struck at the apex ball), and its refusals; and a MODE_CHOOSE request decided by the
// player it names.
#include "planner/node/break_request.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lcmtypes/names.h"
#include "planner/node/planner_node.h"
#include "planner/node/testing/node_harness.h"
#include "sim/physics/ball_state.h"
#include "sim/table/rack.h"

namespace billiard::planner_node::testing {
namespace {

// The head string lies a quarter of the table's length from the head cushion (WPA).
constexpr double kHeadString = 0.25;

shot_request_t Break(int64_t id, int8_t rules) {
  shot_request_t q = Request(id, shot_request_t::BALL_BY_CLASS, 0.0, 0.0);
  q.ball_class = ball_state_t::CLASS_CUE;
  q.mode = shot_request_t::MODE_BREAK;
  q.rules = rules;
  return q;
}

class BreakRequestTest : public PlannerNodePotTest {
 protected:
  // The rack of `kind` (seed 3) as the estimator names it: the cue ball track 20, ball n track n.
  std::vector<table::SceneBall> PublishRack(table::RackKind kind) {
    const std::vector<table::SceneBall> rack = table::Rack(kind, table_, params_.ball.radius, 3);
    std::vector<ball_state_t> seen;
    for (const table::SceneBall& b : rack) {
      const int8_t cls = b.id == 0 ? ball_state_t::CLASS_CUE : static_cast<int8_t>(b.id);
      seen.push_back(Classed(b.id == 0 ? 20 : b.id, b.state[physics::kX], b.state[physics::kY],
                             cls, 0.9f));
    }
    PublishTable(seen);
    return rack;
  }
};

// The apex: the object ball nearest the head string.
Eigen::Vector2d Apex(const std::vector<table::SceneBall>& rack) {
  Eigen::Vector2d apex(1e9, 0.0);
  for (const table::SceneBall& b : rack) {
    if (b.id != 0 && b.state[physics::kX] < apex.x()) apex = b.state.head<2>();
  }
  return apex;
}

TEST_F(BreakRequestTest, NineBallsBreakPlacesTheCueBallOnTheHeadStringAndHitsTheApexFull) {
  const Eigen::Vector2d apex = Apex(PublishRack(table::RackKind::kNineBall));
  const cue_command_t c = AskOk(Break(1, shot_request_t::RULES_NINE_BALL));
  EXPECT_EQ(c.mode, shot_request_t::MODE_BREAK);
  EXPECT_EQ(c.ball_id, 20);
  ASSERT_EQ(c.has_cue_placement, 1);
  EXPECT_NEAR(c.cue_placement[0], kHeadString * table_.length, 1e-12);
  // Off the long axis: the break is not the old one from the head spot.
  EXPECT_GT(std::abs(c.cue_placement[1] - 0.5 * table_.width), 0.1);
  EXPECT_EQ(c.start[0], c.cue_placement[0]);
  // Full on the apex: the heading is the line of centres.
  const Eigen::Vector2d line = apex - Eigen::Vector2d(c.cue_placement[0], c.cue_placement[1]);
  EXPECT_NEAR(c.heading, std::atan2(line.y(), line.x()), 1e-12);
  EXPECT_GT(c.cue_speed, 5.0);
  EXPECT_EQ(c.safety, 0);
}

// Every ruleset goes out by its name's code and comes back as itself.
TEST(RulesOf, EveryRulesetRoundTripsThroughTheRequest) {
  for (rules::Rules r : {rules::Rules::kAny, rules::Rules::kNineBall, rules::Rules::kEightBall,
                         rules::Rules::kEightBallSolids, rules::Rules::kEightBallStripes}) {
    shot_request_t q{};
    q.rules = messages::ShotRulesCode(rules::RulesName(r));
    EXPECT_GE(q.rules, 0) << rules::RulesName(r);
    EXPECT_EQ(RulesOf(q), r) << rules::RulesName(r);
  }
  EXPECT_EQ(messages::ShotRulesCode("snooker"), -1);
  EXPECT_EQ(messages::ShotRulesName(5), "");
}

TEST_F(BreakRequestTest, EachGameBreaksItsOwnWay) {
  PublishRack(table::RackKind::kEightBall);
  const cue_command_t eight = AskOk(Break(1, shot_request_t::RULES_EIGHT_BALL));
  PublishRack(table::RackKind::kNineBall);
  const cue_command_t nine = AskOk(Break(2, shot_request_t::RULES_NINE_BALL));
  EXPECT_NE(eight.cue_placement[1], nine.cue_placement[1]);
}

TEST_F(BreakRequestTest, ABreakRefusesATableWithoutAnObjectBallAndRulesWithoutARack) {
  PublishTable({Classed(20, 0.6, 0.6, ball_state_t::CLASS_CUE, 0.9f)});
  const auto alone = Ask(Break(1, shot_request_t::RULES_NINE_BALL));
  ASSERT_TRUE(alone);
  EXPECT_EQ(alone->status, cue_command_t::STATUS_NO_SUCH_BALL) << alone->reason;
  PublishRack(table::RackKind::kNineBall);
  const auto any = Ask(Break(2, shot_request_t::RULES_ANY));
  ASSERT_TRUE(any);
  EXPECT_EQ(any->status, cue_command_t::STATUS_INVALID) << any->reason;
}

// A match's requests name their player: each is made once and decides its own way; a name no
// player has is refused, and the node goes on.
TEST_F(PlannerNodePotTest, AChoiceIsDecidedByThePlayerTheRequestNames) {
  PublishPotTable();
  shot_request_t q = Request(1, shot_request_t::BALL_BY_CLASS, 0.0, 0.0);
  q.ball_class = ball_state_t::CLASS_CUE;
  q.mode = shot_request_t::MODE_CHOOSE;
  q.rules = shot_request_t::RULES_NINE_BALL;
  q.player = "easiest-looking";
  const cue_command_t easiest = AskOk(q);
  q.request_id = 2;
  q.player = "";  // the node's own, ours
  const cue_command_t ours = AskOk(q);
  EXPECT_EQ(easiest.object_ball_id, kObject);
  EXPECT_EQ(ours.object_ball_id, kObject);
  // Ours confirms its probability on samples of its own; the easiest-looking reports none.
  EXPECT_GT(ours.probability_stderr, 0.0);
  EXPECT_NE(easiest.success_probability, ours.success_probability);
  q.request_id = 3;
  q.player = "nobody";
  const auto refused = Ask(q);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->status, cue_command_t::STATUS_INVALID);
  EXPECT_NE(refused->reason.find("unknown player 'nobody'"), std::string::npos) << refused->reason;
  q.request_id = 4;
  q.player = "easiest-looking";
  EXPECT_EQ(AskOk(q).heading, easiest.heading);
}

}  // namespace
}  // namespace billiard::planner_node::testing
