// MODE_POT: through the node, a pot planned from the table state and simulated independently with
// sim/table/'s TableSimulation under `simulate --scene`'s motion (the ball drops, the cue ball
// touches it first and rests where the plan said), a cue-ball target met, and every refusal;
// alone, an answer that does not depend on the order the table state lists its balls in.
#include "planner/node/pot_request.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "planner/node/command_writing.h"
#include "planner/node/testing/node_harness.h"
#include "sim/model_choice/model_choice.h"
#include "sim/physics/ball_state.h"
#include "sim/table/table_simulation.h"

namespace billiard::planner_node::testing {
namespace {

TEST_F(PlannerNodePotTest, APotPlannedFromTheTableStatePotsTheBallWhenSimulated) {
  PublishPotTable();
  const cue_command_t c = AskOk(Pot(1, kObject, "lower_left"));
  EXPECT_EQ(c.mode, shot_request_t::MODE_POT);
  EXPECT_EQ(c.ball_id, kCueTrack);
  EXPECT_EQ(c.object_ball_id, kObject);
  EXPECT_EQ(c.pocket, "lower_left");
  EXPECT_NE(c.kind, shot_request_t::KIND_ANY);
  EXPECT_GT(c.margin_deg[0], 0.0);
  EXPECT_GT(c.margin_deg[1], 0.0);
  EXPECT_LE(c.speed_window[0], c.cue_speed);
  EXPECT_GE(c.speed_window[1], c.cue_speed);
  EXPECT_EQ(c.start[0], 1.0);
  EXPECT_EQ(c.start[1], 0.45);
  // The paths by the table state's ids: the cue ball's (also in path) and ball 5's, which ends
  // in the pocket's corner; the ball out of the way does not move.
  const ball_path_t* cue_path = PathOf(c, kCueTrack);
  const ball_path_t* object_path = PathOf(c, kObject);
  ASSERT_TRUE(cue_path && object_path);
  EXPECT_EQ(PathOf(c, kOther), nullptr);
  EXPECT_EQ(cue_path->points, c.path);
  EXPECT_NEAR(cue_path->points.front()[0], 1.0, 1e-12);
  EXPECT_NEAR(object_path->points.back()[0] + object_path->points.back()[1], 0.0, 0.15);
  EXPECT_EQ(c.cue_rest[0], c.predicted_final[0]);
  EXPECT_EQ(LogLinesContaining("request 1 (ball 3, pot ball 5 in lower_left): ok"), 1);

  // The launch simulated by the table alone, with `simulate --scene`'s default motion: ball 5
  // drops in the lower-left pocket, the cue ball touches it first, stays on the table and rests
  // where the plan said.
  std::vector<table::SceneBall> scene = {
      {0, physics::MakeBallState(1.0, 0.45, c.v0[0], c.v0[1], c.w0[0], c.w0[1], c.w0[2])},
      {kObject, physics::MakeBallState(0.5, 0.3, 0, 0, 0, 0, 0)},
      {9, physics::MakeBallState(2.0, 1.0, 0, 0, 0, 0, 0)}};
  table::TableSimulationOptions motion;
  motion.five_dof = model_choice::TableMotion(params_);
  table::TableSimulation sim(table_, params_, scene, motion);
  sim.Run();
  EXPECT_EQ(sim.pocket(1).value_or("none"), "lower_left");
  EXPECT_FALSE(sim.pocket(0)) << "a scratch in " << *sim.pocket(0);
  EXPECT_FALSE(sim.pocket(2));
  for (const table::TableEvent& e : sim.events()) {
    if (e.type != table::EventType::kBallBall) continue;
    EXPECT_EQ(e.ball + e.other, kObject) << "the cue ball's first contact is ball 5";
    break;
  }
  EXPECT_NEAR(sim.State(0)[physics::kX], c.cue_rest[0], 1e-6);
  EXPECT_NEAR(sim.State(0)[physics::kY], c.cue_rest[1], 1e-6);
}

TEST_F(PlannerNodePotTest, APotWithACueBallTargetLeavesTheCueBallThere) {
  PublishPotTable();
  shot_request_t q = Pot(1, kObject, "lower_left");
  q.has_cue_target = 1;
  q.cue_target[0] = 0.9;
  q.cue_target[1] = 0.5;
  q.cue_radius = 0.05;
  const auto answer = Ask(q);
  ASSERT_TRUE(answer);
  ASSERT_EQ(Status(*answer), kOk) << answer->reason;
  EXPECT_LE(std::hypot(answer->cue_rest[0] - 0.9, answer->cue_rest[1] - 0.5), 0.05 + 1e-9);

  // Just past ball 9 from where the cue ball comes off ball 5: no stroke stops it there.
  q.request_id = 2;
  q.cue_target[0] = 2.0 + 0.06;
  q.cue_target[1] = 1.0;
  q.cue_radius = 0.0;
  const auto unreachable = Ask(q);
  ASSERT_TRUE(unreachable);
  EXPECT_EQ(Status(*unreachable), cue_command_t::STATUS_TARGET_UNREACHABLE) << unreachable->reason;
  EXPECT_EQ(unreachable->cue_speed, 0.0);
}

TEST_F(PlannerNodePotTest, BadPotRequestsAreRefusedWithAReasonAndTheNodeKeepsAnswering) {
  PublishPotTable();
  struct Case {
    shot_request_t request;
    int status;
    std::string says;
  };
  std::vector<Case> cases = {
      {Pot(1, 42, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL, "no ball 42"},
      {Pot(2, kCueTrack, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL, "struck"},
      {Pot(3, kObject, "nowhere"), cue_command_t::STATUS_NO_SUCH_POCKET, "nowhere"},
      {Pot(4, kObject, "lower_left"), kInvalid, "non-finite"},
      {Pot(5, kObject, "lower_left"), kOffTable, "off the pool-9ft"},
      {Pot(6, kObject, "lower_left"), kInvalid, "kind"},
      {Pot(7, shot_request_t::BALL_BY_CLASS, "lower_left"), cue_command_t::STATUS_NO_SUCH_BALL,
       "class 12"},
      {Pot(8, kObject, ""), kInvalid, "pocket"},
      {Pot(9, kObject, "lower_left"), kInvalid, "non-finite"},
  };
  cases[3].request.has_cue_target = 1;
  cases[3].request.cue_target[0] = kNaN;
  cases[4].request.has_cue_target = 1;
  cases[4].request.cue_target[0] = 5.0;
  cases[4].request.cue_target[1] = 0.5;
  cases[5].request.kind = 9;
  cases[6].request.object_ball_class = 12;
  cases[8].request.side_spin = kNaN;
  for (const Case& k : cases) {
    const auto answer = Ask(k.request);
    ASSERT_TRUE(answer) << "request " << k.request.request_id;
    EXPECT_EQ(Status(*answer), k.status)
        << "request " << k.request.request_id << ": " << answer->reason;
    EXPECT_NE(answer->reason.find(k.says), std::string::npos)
        << "request " << k.request.request_id << ": " << answer->reason;
    EXPECT_EQ(std::count(answer->reason.begin(), answer->reason.end(), '\n'), 0);
    EXPECT_EQ(answer->cue_speed, 0.0) << "request " << k.request.request_id;
    EXPECT_EQ(answer->num_ball_paths, 0) << "request " << k.request.request_id;
  }
  // A ball the latest table state does not name is gone (pocketed, or lost by the estimator),
  // though a point request could still strike it from where it was last seen.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f)}, 1'100'000);
  shot_request_t later = Pot(10, kObject, "lower_left");
  later.utime = 1'100'000;
  const auto gone = Ask(later);
  ASSERT_TRUE(gone);
  EXPECT_EQ(Status(*gone), cue_command_t::STATUS_NO_SUCH_BALL) << gone->reason;
  EXPECT_NE(gone->reason.find("latest table state"), std::string::npos) << gone->reason;

  // Still answering: the same pot, planned, once the ball is seen again; and a point request.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f)},
               1'100'010);
  later.request_id = 11;
  later.utime = 1'100'010;
  AskOk(later);
  shot_request_t point = Request(12, kCueTrack, 1.5, 0.6);
  point.utime = 1'100'010;
  AskOk(point);
}

// The pot planner's own refusals go out with their status: a ball in the direct line, and a cut
// of 90 degrees.
TEST_F(PlannerNodePotTest, ThePotPlannersRefusalsGoOutWithTheirStatus) {
  // The cue ball square to the line from ball 5 to the pocket.
  PublishTable(
      {Classed(kCueTrack, 0.5 - 0.3 * 0.514, 0.3 + 0.3 * 0.857, ball_state_t::CLASS_CUE, 0.9f),
       Classed(kObject, 0.5, 0.3, 5, 0.9f)});
  shot_request_t thin = Pot(1, kObject, "lower_left");
  thin.kind = shot_request_t::KIND_DIRECT;
  const auto too_thin = Ask(thin);
  ASSERT_TRUE(too_thin);
  EXPECT_EQ(Status(*too_thin), cue_command_t::STATUS_TOO_THIN) << too_thin->reason;

  // Ball 7 in the line from ball 5 to the pocket.
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.5, 0.3, 5, 0.9f), Ball(7, 0.25, 0.15)},
               1'000'010);
  shot_request_t blocked = Pot(2, kObject, "lower_left");
  blocked.utime = 1'000'010;
  blocked.kind = shot_request_t::KIND_DIRECT;
  const auto in_the_way = Ask(blocked);
  ASSERT_TRUE(in_the_way);
  EXPECT_EQ(Status(*in_the_way), cue_command_t::STATUS_BLOCKED) << in_the_way->reason;
  EXPECT_NE(in_the_way->reason.find("ball 7"), std::string::npos) << in_the_way->reason;
}

// The estimator's touching balls: ball 9, beside the object ball's line to the pocket, measured
// 0.5 mm into it. Settled apart, the pot is planned; a ball 5 mm into another is an impossible
// scene and refused.
TEST_F(PlannerNodePotTest, TouchingBallsSeenOverlappingAreSettledApart) {
  const double r = params_.ball.radius;
  const Eigen::Vector2d k(0.6, 0.3);
  const Eigen::Vector2d mouth = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = (mouth - k).normalized();
  const Eigen::Vector2d beside = k + (2 * r - 5e-4) * Eigen::Vector2d(-along.y(), along.x());
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, k.x(), k.y(), 5, 0.9f),
                Classed(kOther, beside.x(), beside.y(), 9, 0.9f)});
  const cue_command_t c = AskOk(Pot(1, kObject, "lower_left"));
  EXPECT_EQ(c.object_ball_id, kObject);
  PublishTable(
      {Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
       Classed(kObject, 0.6, 0.3, 5, 0.9f), Classed(kOther, 0.6, 0.3 + 2 * r - 5e-3, 9, 0.9f)},
      1'000'020);  // a later state: the node keeps the latest
  const auto answer = Ask(Pot(2, kObject, "lower_left"));
  ASSERT_TRUE(answer);
  EXPECT_EQ(Status(*answer), kInvalid);
  EXPECT_NE(answer->reason.find("overlap"), std::string::npos) << answer->reason;
}

// A pot asked for while the balls still roll is held until the table rests, and planned from
// where they came to rest (the object ball's path starts there).
TEST_F(PlannerNodePotTest, APotWaitsForTheBallsToComeToRest) {
  PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                Classed(kObject, 0.45, 0.28, 5, 0.9f), Ball(7, 2.0, 1.0, 0.4, 0.0)});
  EXPECT_FALSE(Ask(Pot(1, kObject, "lower_left"))) << "answered while ball 7 rolls";
  for (int64_t utime : {1'000'010, 1'000'020, 1'000'030}) {
    EXPECT_FALSE(AnswerTo(1));
    PublishTable({Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                  Classed(kObject, 0.5, 0.3, 5, 0.9f), Ball(7, 2.1, 1.0)},
                 utime);
    RunNode();
  }
  const auto answer = AnswerTo(1);
  ASSERT_TRUE(answer);
  ASSERT_EQ(Status(*answer), kOk) << answer->reason;
  const ball_path_t* object = PathOf(*answer, kObject);
  ASSERT_NE(object, nullptr);
  ASSERT_GT(object->num_points, 0);
  EXPECT_DOUBLE_EQ(object->points[0][0], 0.5);
  EXPECT_DOUBLE_EQ(object->points[0][1], 0.3);
}

TEST_F(PlannerNodePotTest, ThePotDoesNotDependOnTheOrderOfTheTableStatesBalls) {
  table_state_t latest{};
  latest.balls = {Classed(kCueTrack, 1.0, 0.45, ball_state_t::CLASS_CUE, 0.9f),
                  Classed(kObject, 0.5, 0.3, 5, 0.9f), Classed(kOther, 2.0, 1.0, 9, 0.9f)};
  latest.num_balls = static_cast<int32_t>(latest.balls.size());
  const shot_request_t q = Pot(1, kObject, "lower_left");
  const PlannerNodeOptions options;
  const cue_command_t a =
      AnswerPot(q, latest.balls[0], latest, table_, params_, options, ReplyTo(q));
  std::reverse(latest.balls.begin(), latest.balls.end());
  const cue_command_t b =
      AnswerPot(q, latest.balls[2], latest, table_, params_, options, ReplyTo(q));
  ASSERT_EQ(Status(a), kOk) << a.reason;
  EXPECT_EQ(a.heading, b.heading);
  EXPECT_EQ(a.cue_speed, b.cue_speed);
  EXPECT_EQ(a.object_ball_id, kObject);
  EXPECT_EQ(b.object_ball_id, kObject);
  ASSERT_EQ(a.ball_paths.size(), b.ball_paths.size());
  for (std::size_t i = 0; i < a.ball_paths.size(); ++i) {
    EXPECT_EQ(a.ball_paths[i].ball_id, b.ball_paths[i].ball_id);
  }
}

}  // namespace
}  // namespace billiard::planner_node::testing
