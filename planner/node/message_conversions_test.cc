// The planners' statuses and kinds in the messages' terms: each goes out under the name its
// planner gives it, and a kind comes back as it went; a request's spin choice as the planner's.
#include "planner/node/message_conversions.h"

#include <gtest/gtest.h>

#include <string>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/names.h"

namespace billiard::planner_node {
namespace {

TEST(ToMessageStatus, NamesAPlanStatusAsThePlannerDoes) {
  for (const planner::PlanStatus s :
       {planner::PlanStatus::kOk, planner::PlanStatus::kInvalid, planner::PlanStatus::kOffTable,
        planner::PlanStatus::kUnreachable, planner::PlanStatus::kNotConverged, planner::PlanStatus::kCueBlocked}) {
    EXPECT_EQ(messages::CueCommandStatusName(ToMessageStatus(s)), planner::PlanStatusName(s));
  }
}

TEST(ToMessageStatus, NamesAPotStatusAsThePotPlannerDoes) {
  for (const pot::PotStatus s :
       {pot::PotStatus::kOk, pot::PotStatus::kInvalid, pot::PotStatus::kNoSuchBall,
        pot::PotStatus::kNoSuchPocket, pot::PotStatus::kBlocked, pot::PotStatus::kTooThin,
        pot::PotStatus::kNoStroke, pot::PotStatus::kTargetUnreachable}) {
    EXPECT_EQ(messages::CueCommandStatusName(ToMessageStatus(s)), pot::PotStatusName(s));
  }
}

TEST(ToShotKind, IsToMessageKindBackwards) {
  for (const pot::ShotKind k : {pot::ShotKind::kDirect, pot::ShotKind::kBank, pot::ShotKind::kKick,
                                pot::ShotKind::kCurve}) {
    const int8_t kind = ToMessageKind(k);
    EXPECT_EQ(messages::PotKindName(kind), pot::ShotKindName(k));
    ASSERT_TRUE(ToShotKind(kind));
    EXPECT_EQ(*ToShotKind(kind), k);
  }
  EXPECT_FALSE(ToShotKind(shot_request_t::KIND_ANY)) << "any: the planner's choice";
  EXPECT_FALSE(ToShotKind(9));
}

TEST(ToShotRequest, IsFromTheBallToTheTargetWithTheSpinChosen) {
  ball_state_t ball{};
  ball.position[0] = 0.4;
  ball.position[1] = 0.7;
  shot_request_t q{};
  q.target[0] = 1.9;
  q.target[1] = 0.2;
  q.final_speed = 0.3;
  q.side_spin = -6.0;
  q.slide_length = 0.25;
  q.spin = shot_request_t::SPIN_DRAW;
  const planner::ShotRequest draw = ToShotRequest(q, ball);
  EXPECT_EQ(draw.from, Eigen::Vector2d(0.4, 0.7));
  EXPECT_EQ(draw.to, Eigen::Vector2d(1.9, 0.2));
  EXPECT_EQ(draw.final_speed, 0.3);
  EXPECT_EQ(draw.side_spin, -6.0);
  EXPECT_EQ(draw.style, planner::SpinStyle::kDraw);
  EXPECT_FALSE(draw.slide_length) << "a style ignores the slide length";
  q.spin = shot_request_t::SPIN_SLIDE;
  const planner::ShotRequest slide = ToShotRequest(q, ball);
  ASSERT_TRUE(slide.slide_length);
  EXPECT_EQ(*slide.slide_length, 0.25);
}

}  // namespace
}  // namespace billiard::planner_node
