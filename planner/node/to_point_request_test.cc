// MODE_TO_POINT: through the node, the same numbers as PlanShot called directly for every spin
// choice; alone, a refused plan's measurements without a stroke.
#include "planner/node/to_point_request.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>

#include "lcmtypes/names.h"
#include "planner/node/command_writing.h"
#include "planner/node/testing/node_harness.h"
#include "sim/cue/stroke_limits.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/table/table_geometry.h"

namespace billiard::planner_node::testing {
namespace {

TEST_F(PlannerNodeTest, AnswersLikePlanShotCalledDirectly) {
  ASSERT_TRUE(lcm_.good());
  PublishTable({Ball(1, 0.6, 0.5), Ball(2, 2.0, 1.0)});
  shot_request_t q = Request(42, 1, 1.8, 0.9);
  q.final_speed = 0.2;
  q.side_spin = 5.0;
  const cue_command_t c = AskOk(q);
  EXPECT_EQ(c.request_id, 42);
  EXPECT_EQ(c.ball_id, 1);
  EXPECT_EQ(c.utime, q.utime);
  EXPECT_TRUE(c.reason.empty());

  planner::ShotRequest direct;
  direct.from = {0.6, 0.5};
  direct.to = {1.8, 0.9};
  direct.final_speed = 0.2;
  direct.side_spin = 5.0;
  const planner::ShotPlan plan = planner::PlanShot(direct, params_);
  ASSERT_EQ(plan.status, planner::PlanStatus::kOk) << plan.reason;
  // The same request, so the same numbers to the bit: the planner depends on nothing else.
  EXPECT_EQ(c.v0[0], plan.v0.x());
  EXPECT_EQ(c.v0[1], plan.v0.y());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(c.w0[i], plan.w0[i]);
  EXPECT_EQ(c.cue_speed, plan.stroke.speed);
  EXPECT_EQ(c.heading, plan.stroke.heading);
  EXPECT_EQ(c.tip_side, plan.stroke.tip_side);
  EXPECT_EQ(c.tip_height, plan.stroke.tip_height);
  EXPECT_EQ(c.elevation, plan.stroke.elevation);
  EXPECT_EQ(c.iterations, plan.iterations);
  EXPECT_EQ(c.refined_miss_m, plan.refined_miss_m);
  EXPECT_EQ(c.closed_form_miss_m, plan.closed_form_miss_m);
  EXPECT_GT(c.cue_speed, 0.0);

  EXPECT_EQ(c.start[0], 0.6);
  EXPECT_EQ(c.start[1], 0.5);
  ASSERT_GE(c.num_path_points, 2);
  ASSERT_EQ(c.path.size(), static_cast<size_t>(c.num_path_points));
  EXPECT_NEAR(c.path.front()[0], 0.6, 1e-12);
  EXPECT_NEAR(c.path.front()[1], 0.5, 1e-12);
  EXPECT_NEAR(c.path.back()[0], c.predicted_final[0], 1e-12);
  EXPECT_NEAR(c.path.back()[1], c.predicted_final[1], 1e-12);
  EXPECT_LT(std::hypot(c.predicted_final[0] - 1.8, c.predicted_final[1] - 0.9), 1e-3);
  EXPECT_EQ(LogLinesContaining("request 42 (ball 1): ok"), 1);
}

TEST_F(PlannerNodeTest, MapsEverySpinChoiceToThePlannersRequest) {
  PublishTable({Ball(3, 0.4, 0.4)});
  const std::pair<int8_t, std::optional<planner::SpinStyle>> spins[] = {
      {shot_request_t::SPIN_NATURAL, planner::SpinStyle::kNatural},
      {shot_request_t::SPIN_STUN, planner::SpinStyle::kStun},
      {shot_request_t::SPIN_FOLLOW, planner::SpinStyle::kFollow},
      {shot_request_t::SPIN_DRAW, planner::SpinStyle::kDraw},
      {shot_request_t::SPIN_SLIDE, std::nullopt}};
  int64_t id = 100;
  for (const auto& [spin, style] : spins) {
    shot_request_t q = Request(++id, 3, 1.4, 0.7, spin);
    q.final_speed = 0.5;
    q.slide_length = 0.3;
    const auto answer = Ask(q);
    ASSERT_TRUE(answer) << int{spin};
    planner::ShotRequest direct;
    direct.from = {0.4, 0.4};
    direct.to = {1.4, 0.7};
    direct.final_speed = 0.5;
    if (style) {
      direct.style = *style;
    } else {
      direct.slide_length = 0.3;
    }
    const planner::ShotPlan plan = planner::PlanShot(direct, params_);
    EXPECT_EQ(answer->reason, plan.reason) << int{spin};
    EXPECT_EQ(answer->v0[0], plan.v0.x()) << int{spin};
    EXPECT_EQ(answer->w0[0], plan.w0.x()) << int{spin};
    EXPECT_EQ(answer->w0[1], plan.w0.y()) << int{spin};
    std::fprintf(stderr, "spin %d: %s, %d iterations, miss %.2e m (closed form %.2e m), %.0f us\n",
                 int{spin}, messages::CueCommandStatusName(answer->status).c_str(),
                 answer->iterations, answer->refined_miss_m, answer->closed_form_miss_m,
                 answer->solve_us);
  }
}

// The node with the gantry's cue checked against the balls.
class PlannerNodeGantryTest : public PlannerNodeTest {
 protected:
  PlannerNodeGantryTest() : PlannerNodeTest(WithGantry()) {}
  static PlannerNodeOptions WithGantry() {
    PlannerNodeOptions options;
    options.pot.robot = params::LoadRobot("gantry");
    return options;
  }
};

// A ball 1 mm behind the struck one makes the cue rise steeply to clear it; once the estimator
// no longer sees it (pocketed, or the rack cleared away and a new one set), it is no obstacle and
// the cue lies level. The loop's break after a cleared rack was refused (cue_blocked): the planner
// checked the cue against every ball it remembered, among them a cue ball track of the last rack
// lying where the new cue ball stood.
TEST_F(PlannerNodeGantryTest, TheCueClearsTheBallsOnTheTableNotTheBallsNoLongerSeen) {
  constexpr double kSteep = 20.0 * M_PI / 180.0;
  const double behind = 2.0 * params_.ball.radius + 1e-3;
  PublishTable({Ball(1, 0.8, 0.5), Ball(2, 0.8 - behind, 0.5)});
  const cue_command_t raised = AskOk(Request(1, 1, 1.1, 0.5));
  EXPECT_GT(raised.elevation, kSteep);
  PublishTable({Ball(1, 0.8, 0.5)}, 2'000'000);
  const cue_command_t level = AskOk(Request(2, 1, 1.1, 0.5));
  EXPECT_LT(level.elevation, cue::kElevationMargin + 1e-9);
}

TEST(AnswerToPoint, ARefusedPlanGoesOutWithItsMeasurementsAndNoStroke) {
  const physics::ModelParameters params = params::LoadParameters("paper");
  const shot_request_t q = Request(1, 1, 1.5, 0.7, shot_request_t::SPIN_DRAW);
  planner::PlannerOptions unrefined;  // the closed form's launch, centimetres off
  unrefined.max_iterations = 0;
  unrefined.acceptable_miss = 1e-9;
  PlannerNodeOptions options;
  options.planner = unrefined;
  options.pot.robot = std::nullopt;  // the plan alone: the paper's table is not the pool-9ft's
  const cue_command_t c = AnswerToPoint(
      q, Ball(1, 0.5, 0.5), {}, table::BuildTable(params::LoadTableSpec(params::kDefaultTable)),
      params, options, ReplyTo(q));
  EXPECT_EQ(Status(c), cue_command_t::STATUS_NOT_CONVERGED) << c.reason;
  EXPECT_NE(c.reason.find("from the target"), std::string::npos) << c.reason;
  EXPECT_GT(c.refined_miss_m, 1e-4) << "the miss says by how much";
  EXPECT_EQ(c.refined_miss_m, c.closed_form_miss_m);
  EXPECT_GE(c.num_path_points, 2);
  for (double x : {c.cue_speed, c.heading, c.tip_side, c.tip_height, c.elevation}) {
    EXPECT_EQ(x, 0.0);
  }
  EXPECT_EQ(c.request_id, 1);
}

}  // namespace
}  // namespace billiard::planner_node::testing
