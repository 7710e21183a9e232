// The answer written into its cue_command_t: its ids, a refusal that cannot move the cue, a plan's
// and a pot's results, and what the receiver's checks would drop turned into a refusal.
#include "planner/node/command_writing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

#include "lcmtypes/message_checks.h"

namespace billiard::planner_node {
namespace {

shot_request_t PotRequest() {
  shot_request_t q{};
  q.utime = 123;
  q.request_id = 9;
  q.ball_id = shot_request_t::BALL_BY_CLASS;
  q.ball_class = ball_state_t::CLASS_CUE;
  q.mode = shot_request_t::MODE_POT;
  q.object_ball_id = 5;
  q.pocket = "lower_left";
  q.kind = shot_request_t::KIND_BANK;
  return q;
}

TEST(ReplyTo, CarriesTheRequestsIdsAndAPotsBallPocketAndKindWhenItChecks) {
  const shot_request_t q = PotRequest();
  ASSERT_EQ(messages::Check(q), "");
  const cue_command_t c = ReplyTo(q);
  EXPECT_EQ(c.utime, 123);
  EXPECT_EQ(c.request_id, 9);
  EXPECT_EQ(c.ball_id, shot_request_t::BALL_BY_CLASS);
  EXPECT_EQ(c.mode, shot_request_t::MODE_POT);
  EXPECT_EQ(c.object_ball_id, 5);
  EXPECT_EQ(c.pocket, "lower_left");
  EXPECT_EQ(c.kind, shot_request_t::KIND_BANK);

  shot_request_t unchecked = q;
  unchecked.pocket = "";
  EXPECT_NE(messages::Check(unchecked), "");
  const cue_command_t u = ReplyTo(unchecked);
  EXPECT_EQ(u.request_id, 9);
  EXPECT_EQ(u.mode, 0);
  EXPECT_EQ(u.object_ball_id, 0);

  shot_request_t choose = q;
  choose.mode = shot_request_t::MODE_CHOOSE;
  choose.rules = shot_request_t::RULES_NINE_BALL;
  EXPECT_EQ(ReplyTo(choose).object_ball_id, -1) << "none chosen yet";
}

TEST(WritePlan, AStrokeOnlyWithAnOkPlan) {
  planner::ShotPlan plan;
  plan.status = planner::PlanStatus::kOk;
  plan.stroke.speed = 2.5;
  plan.stroke.heading = 0.3;
  plan.refined_miss_m = 4e-7;
  plan.predicted_path = {{0.1, 0.2}, {0.3, 0.4}};
  cue_command_t ok{};
  WritePlan(plan, &ok);
  EXPECT_EQ(ok.status, cue_command_t::STATUS_OK);
  EXPECT_EQ(ok.cue_speed, 2.5);
  EXPECT_EQ(ok.num_path_points, 2);
  EXPECT_EQ(ok.path.back()[1], 0.4);
  EXPECT_TRUE(ok.reason.empty());

  plan.status = planner::PlanStatus::kNotConverged;
  cue_command_t refused{};
  WritePlan(plan, &refused);
  EXPECT_EQ(refused.status, cue_command_t::STATUS_NOT_CONVERGED);
  EXPECT_EQ(refused.cue_speed, 0.0);
  EXPECT_EQ(refused.heading, 0.0);
  EXPECT_EQ(refused.refined_miss_m, 4e-7) << "the measurements go out with a refusal";
  EXPECT_EQ(refused.reason, "not_converged") << "the status's name when the plan gives none";
}

TEST(WritePot, NamesTheBallsByTheTableStatesIds) {
  pot::PotPlan plan;
  plan.status = pot::PotStatus::kOk;
  plan.kind = pot::ShotKind::kKick;
  plan.stroke.speed = 1.5;
  plan.cue_rest = {1.2, 0.8};
  plan.paths = {{0, {{1.0, 0.5}, {1.2, 0.8}}}, {4, {{0.5, 0.3}, {0.1, 0.1}}}};
  cue_command_t c{};
  WritePot(plan, {{0, 31}, {4, 12}}, &c);
  EXPECT_EQ(c.status, cue_command_t::STATUS_OK);
  EXPECT_EQ(c.kind, shot_request_t::KIND_KICK);
  ASSERT_EQ(c.num_ball_paths, 2);
  EXPECT_EQ(c.ball_paths[0].ball_id, 31);
  EXPECT_EQ(c.ball_paths[1].ball_id, 12);
  EXPECT_EQ(c.path, c.ball_paths[0].points) << "the cue ball's path is the command's";
  EXPECT_EQ(c.predicted_final[0], 1.2);

  pot::PotPlan blocked;
  blocked.status = pot::PotStatus::kBlocked;
  cue_command_t refused{};
  WritePot(blocked, {}, &refused);
  EXPECT_EQ(refused.status, cue_command_t::STATUS_BLOCKED);
  EXPECT_EQ(refused.reason, "blocked");
  EXPECT_EQ(refused.cue_speed, 0.0);
}

TEST(Sendable, AnOkTheReceiverWouldDropIsNoOk) {
  cue_command_t c = ReplyTo(PotRequest());
  c.status = cue_command_t::STATUS_OK;
  c.cue_speed = 2.0;
  ASSERT_EQ(messages::Check(c), "");
  EXPECT_EQ(Sendable(c).cue_speed, 2.0) << "what passes goes out as it is";
  c.heading = std::numeric_limits<double>::quiet_NaN();
  const cue_command_t out = Sendable(c);
  EXPECT_EQ(out.status, cue_command_t::STATUS_NOT_CONVERGED);
  EXPECT_NE(out.reason.find("not a valid command"), std::string::npos) << out.reason;
  EXPECT_EQ(out.cue_speed, 0.0);
  EXPECT_EQ(out.request_id, 9);
  EXPECT_EQ(out.pocket, "lower_left");
  EXPECT_EQ(messages::Check(out), "");
}

TEST(Refusal, SetsTheStatusAndTheReason) {
  const cue_command_t c = Refusal(ReplyTo(PotRequest()), cue_command_t::STATUS_BUSY, "full");
  EXPECT_EQ(c.status, cue_command_t::STATUS_BUSY);
  EXPECT_EQ(c.reason, "full");
  EXPECT_EQ(c.request_id, 9);
}

}  // namespace
}  // namespace billiard::planner_node
