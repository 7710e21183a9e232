// MODE_CHOOSE: through the node, a choice under nine-ball rules (its pot played by the table
// alone, from where the cue ball is and with ball in hand) and every refusal; alone, a ball seen
// dropping into a pocket left out of the choice.
#include "planner/node/choose_request.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "planner/node/command_writing.h"
#include "planner/node/planner_node.h"
#include "planner/players/players.h"
#include "planner/node/testing/node_harness.h"
#include "sim/model_choice/model_choice.h"
#include "sim/physics/ball_state.h"
#include "sim/table/table_simulation.h"

namespace billiard::planner_node::testing {
namespace {

// "Choose and play" on the pot table: the cue ball by class, under nine-ball rules.
shot_request_t Choose(int64_t id, bool ball_in_hand,
                      int8_t rules = shot_request_t::RULES_NINE_BALL) {
  shot_request_t q = Request(id, shot_request_t::BALL_BY_CLASS, 0.0, 0.0);
  q.ball_class = ball_state_t::CLASS_CUE;
  q.mode = shot_request_t::MODE_CHOOSE;
  q.rules = rules;
  q.ball_in_hand = ball_in_hand ? 1 : 0;
  return q;
}

// The chosen stroke played from `cue` by the table alone, without noise, with `simulate
// --scene`'s motion: the pocket ball 5 (scene id kObject) drops in, "" if none, and whether the
// cue ball's first contact is ball 5 and it stays on the table.
struct Played {
  std::string pocket;
  bool first_contact_5 = false;
  bool scratch = true;
};
Played PlayChosen(const table::TableGeometry& table, const physics::ModelParameters& params,
                  const cue_command_t& c, const Eigen::Vector2d& cue) {
  std::vector<table::SceneBall> scene = {
      {0, physics::MakeBallState(cue.x(), cue.y(), c.v0[0], c.v0[1], c.w0[0], c.w0[1], c.w0[2])},
      {5, physics::MakeBallState(0.5, 0.3, 0, 0, 0, 0, 0)},
      {9, physics::MakeBallState(2.0, 1.0, 0, 0, 0, 0, 0)}};
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(params);
  table::TableSimulation sim(table, params, scene, motion);
  sim.Run();
  Played played;
  played.pocket = sim.pocket(1).value_or("");
  played.scratch = sim.pocket(0).has_value();
  for (const table::TableEvent& e : sim.events()) {
    if (e.type != table::EventType::kBallBall) continue;
    played.first_contact_5 = e.ball + e.other == 5;
    break;
  }
  return played;
}

TEST_F(PlannerNodePotTest, AChoiceUnderNineBallRulesPlaysTheLowestBallAndPotsItWhenSimulated) {
  PublishPotTable();
  const cue_command_t c = AskOk(Choose(1, false));
  EXPECT_EQ(c.mode, shot_request_t::MODE_CHOOSE);
  EXPECT_EQ(c.ball_id, kCueTrack);
  EXPECT_EQ(c.object_ball_id, kObject) << "the 5 is the lowest: the 9 may not be hit first";
  EXPECT_FALSE(c.pocket.empty());
  EXPECT_EQ(c.has_cue_placement, 0);
  EXPECT_GT(c.success_probability, 0.5);
  EXPECT_GT(c.probability_stderr, 0.0);
  EXPECT_EQ(c.start[0], 1.0);
  const Played played = PlayChosen(table_, params_, c, {1.0, 0.45});
  EXPECT_EQ(played.pocket, c.pocket);
  EXPECT_TRUE(played.first_contact_5);
  EXPECT_FALSE(played.scratch);

  // Ball in hand: the cue ball placed clear of the others, the stroke planned from there.
  const cue_command_t h = AskOk(Choose(2, true));
  ASSERT_EQ(h.has_cue_placement, 1);
  EXPECT_EQ(h.start[0], h.cue_placement[0]);
  EXPECT_EQ(h.start[1], h.cue_placement[1]);
  const Eigen::Vector2d placed(h.cue_placement[0], h.cue_placement[1]);
  EXPECT_TRUE(table_.OnSurface(placed, params_.ball.radius));
  for (const Eigen::Vector2d& other : {Eigen::Vector2d(0.5, 0.3), Eigen::Vector2d(2.0, 1.0)}) {
    EXPECT_GE((placed - other).norm(), 2 * params_.ball.radius);
  }
  EXPECT_EQ(h.object_ball_id, kObject);
  EXPECT_GE(h.success_probability, c.success_probability - 2 * c.probability_stderr)
      << "the cue ball anywhere is no worse than where it was";
  const Played from_hand = PlayChosen(table_, params_, h, placed);
  EXPECT_EQ(from_hand.pocket, h.pocket);
  EXPECT_FALSE(from_hand.scratch);
  // The same request again, on the same table: the same answer, for a log to replay.
  EXPECT_EQ(node_.Answer(Choose(2, true)).heading, h.heading);
}

TEST_F(PlannerNodePotTest, BadChoiceRequestsAreRefusedWithAReasonAndTheNodeKeepsAnswering) {
  PublishPotTable();
  shot_request_t rules = Choose(1, false, 7);
  shot_request_t in_hand = Choose(2, false);
  in_hand.ball_in_hand = 2;
  for (const auto& [request, says] : {std::pair{rules, "rules"}, {in_hand, "ball_in_hand"}}) {
    const auto answer = Ask(request);
    ASSERT_TRUE(answer);
    EXPECT_EQ(Status(*answer), kInvalid);
    EXPECT_NE(answer->reason.find(says), std::string::npos) << answer->reason;
    EXPECT_EQ(answer->cue_speed, 0.0);
  }
  // A table of the cue ball alone has nothing to play; one with a ball moving is no table yet:
  // the choice waits for the balls to rest (three states).
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f)}, 1'000'100);
  const auto empty = Ask(Choose(3, false));
  ASSERT_TRUE(empty);
  EXPECT_EQ(Status(*empty), cue_command_t::STATUS_NO_SUCH_BALL) << empty->reason;
  PublishTable(
      {Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f), Ball(7, 2.0, 1.0, 0.4, 0.0)},
      1'000'200);
  EXPECT_FALSE(Ask(Choose(4, false))) << "chose while ball 7 rolls";
  for (int64_t utime : {1'000'300, 1'000'310, 1'000'320}) {
    PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                  Classed(kObject, 0.5, 0.3, 5, 0.9f), Classed(kOther, 2.0, 1.0, 9, 0.9f)},
                 utime);
  }
  RunNode();
  const auto chosen = AnswerTo(4);
  ASSERT_TRUE(chosen);
  EXPECT_EQ(Status(*chosen), kOk) << chosen->reason;
  EXPECT_EQ(chosen->object_ball_id, kObject);
}

// The 5 seen over the upper-right pocket's mouth (the estimator's last frames of it): no ball to
// play, so under nine-ball rules the 9, where the pot table's 5 is, is the lowest on the table
// and the one to pot, whoever chooses.
TEST_F(PlannerNodePotTest, ABallSeenDroppingIntoAPocketIsLeftOut) {
  table_state_t latest{};
  const Eigen::Vector2d mouth(table_.length - 0.01, table_.width - 0.01);
  latest.balls = {Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                  Classed(kObject, mouth.x(), mouth.y(), 5, 0.9f),
                  Classed(kOther, 0.5, 0.3, 9, 0.9f)};
  latest.num_balls = static_cast<int32_t>(latest.balls.size());
  const shot_request_t q = Choose(1, false);
  PlannerNodeOptions options;
  batch::ThreadPool pool(2);
  for (const std::string& name : players::PlayerNames()) {
    const cue_command_t c = AnswerChoice(q, latest.balls[0], latest, table_, params_, options,
                                         *players::MakePlayer(name), pool, ReplyTo(q));
    ASSERT_EQ(Status(c), kOk) << name << ": " << c.reason;
    EXPECT_EQ(c.object_ball_id, kOther) << name << ": the 5 is gone";
  }
}

// A node is started with a player it knows: an unknown one is named at construction, never met
// at the first choice.
TEST(PlannerNodePlayer, AnUnknownPlayerIsRefusedWhenTheNodeIsMade) {
  lcm::LCM lcm("memq://");
  PlannerNodeOptions options;
  options.player = "nosuch";
  try {
    PlannerNode node(lcm, params::LoadParameters("pool"), options);
    ADD_FAILURE() << "a node with player nosuch was made";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("nosuch"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace billiard::planner_node::testing
