#include "planner/cue_planning.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/cue/clearance.h"
#include "sim/cue/stroke_limits.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/physics/simulator.h"

namespace billiard::planner {
namespace {

constexpr double kDegree = M_PI / 180.0;

class CuePlanningTest : public testing::Test {
 protected:
  physics::ModelParameters params_ = params::LoadParameters("pool");
  CueSetting gantry_{params::LoadRobot("gantry"),
                     table::BuildTable(params::LoadTableSpec(params::kDefaultTable)),
                     {}};

  // docs/planning.md's first request: 0.5 m off the left rail, the ball sent away from it, so
  // that the gantry's 0.5 m cue lies over the rail.
  static ShotRequest OffTheLeftRail(double side_spin) {
    ShotRequest q;
    q.from = {0.5, 0.5};
    q.to = {1.5, 0.8};
    q.final_speed = 0.3;
    q.style = SpinStyle::kStun;
    q.side_spin = side_spin;
    return q;
  }

  cue::CueClearance ClearanceOf(const ShotRequest& q, const physics::CueStroke& stroke) const {
    return cue::Clearance(gantry_.table, params_.ball.radius, {table::AtRest(0, q.from.x(), q.from.y())}, 0, stroke,
                          gantry_.robot);
  }

  // Where the plan's stroke, struck by the cue model and simulated on its own, arrives.
  Eigen::Vector2d Played(const ShotRequest& q, const ShotPlan& plan) const {
    const physics::BallState launch = physics::StrikeBall(plan.stroke, q.from, params_);
    return physics::SimulateArrival(params_, launch, q.final_speed, 60.0).state.head<2>();
  }
};

// The level cue meets the left rail; the plan rises to the least elevation that clears and its
// margin, clears, and its stroke (struck and simulated apart from the planner) still arrives.
TEST_F(CuePlanningTest, AStrokeOverTheRailIsPlayedAboveItAndStillArrives) {
  const ShotRequest q = OffTheLeftRail(0.0);
  const ShotPlan plan = PlanShotForRobot(q, params_, {}, gantry_);
  ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.reason;
  physics::CueStroke level = plan.stroke;
  level.elevation = 0.0;
  EXPECT_FALSE(ClearanceOf(q, level).clears);
  const cue::ClearingElevation least =
      cue::LeastClearingElevation(gantry_.table, params_.ball.radius, {table::AtRest(0, 0.5, 0.5)}, 0, plan.stroke,
                                  gantry_.robot);
  ASSERT_TRUE(least.elevation);
  EXPECT_NEAR(plan.stroke.elevation, *least.elevation + cue::kElevationMargin, 1e-9);
  EXPECT_TRUE(ClearanceOf(q, plan.stroke).clears);
  ASSERT_TRUE(plan.clearance);
  EXPECT_TRUE(plan.clearance->clears);
  EXPECT_LT((Played(q, plan) - q.to).norm(), 1e-4);
}

// Without side spin an elevated cue gives the level launch (the table takes the rest): the same
// launch as the level plan, from a stroke with a smaller offset and a faster cue.
TEST_F(CuePlanningTest, WithoutSideSpinTheElevatedLaunchIsTheLevelOne) {
  ShotRequest q = OffTheLeftRail(0.0);
  q.style = SpinStyle::kFollow;
  const ShotPlan raised = PlanShotForRobot(q, params_, {}, gantry_);
  const ShotPlan level = PlanShot(q, params_);
  ASSERT_EQ(raised.status, PlanStatus::kOk) << raised.reason;
  ASSERT_EQ(level.status, PlanStatus::kOk) << level.reason;
  EXPECT_LT((raised.v0 - level.v0).norm(), 1e-6);
  EXPECT_LT((raised.w0 - level.w0).norm(), 1e-4);
  EXPECT_LT(std::abs(raised.stroke.tip_height), std::abs(level.stroke.tip_height));
  EXPECT_GT(raised.stroke.speed, level.stroke.speed);
}

// With side spin the raised cue also spins the ball about its travel (w . e = wz tan(elevation)
// for the impulse tilted down, perpendicular to the spin it gives): the ball swerves, and the
// plan, made with it, still arrives when its stroke is struck and simulated apart.
TEST_F(CuePlanningTest, WithSideSpinTheRaisedCueSwervesTheBallAndThePlanKnowsIt) {
  const ShotRequest q = OffTheLeftRail(-15.0);
  const ShotPlan plan = PlanShotForRobot(q, params_, {}, gantry_);
  ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.reason;
  ASSERT_GT(plan.stroke.elevation, 1.0 * kDegree);
  // The cue model, struck forward, gives the launch the plan was refined with.
  const physics::BallState launch = physics::StrikeBall(plan.stroke, q.from, params_);
  EXPECT_LT((launch.segment<2>(physics::kVx) - plan.v0).norm(), 1e-9);
  EXPECT_LT((launch.segment<3>(physics::kWx) - plan.w0).norm(), 1e-6);
  const Eigen::Vector2d e = plan.v0.normalized();
  EXPECT_GT(plan.w0.head<2>().dot(e) / plan.w0.z(), 0.5 * std::tan(plan.stroke.elevation));
  EXPECT_LT((Played(q, plan) - q.to).norm(), 1e-4);
}

// A robot that cannot raise its cue over the rail: nothing in its range clears.
TEST_F(CuePlanningTest, AStrokeNothingInRangeClearsIsCueBlocked) {
  const ShotRequest q = OffTheLeftRail(0.0);
  CueSetting low = gantry_;
  low.robot.elevation.max = 0.0;
  const ShotPlan plan = PlanShotForRobot(q, params_, {}, low);
  EXPECT_EQ(plan.status, PlanStatus::kCueBlocked);
  EXPECT_NE(plan.reason.find("the left rail"), std::string::npos) << plan.reason;
}

// A fast stroke over the rail would hop the ball off the cloth: refused, with the hop, as the
// request fixes the pace; the same stroke from the table's middle is played level and planned.
TEST_F(CuePlanningTest, AFastRaisedStrokeThatWouldHopIsRefusedWithTheHop) {
  ShotRequest q = OffTheLeftRail(0.0);
  q.from = {0.06, 0.5};
  q.style = SpinStyle::kNatural;
  q.final_speed = 3.0;
  const ShotPlan plan = PlanShotForRobot(q, params_, {}, gantry_);
  EXPECT_EQ(plan.status, PlanStatus::kUnreachable) << plan.reason;
  EXPECT_NE(plan.reason.find("would hop the ball"), std::string::npos) << plan.reason;
  ASSERT_TRUE(plan.clearance);
  EXPECT_GT(cue::HopHeight(plan.stroke, q.from, params_), cue::kMaxHopOnTheCloth);
  q.from = {1.0, 0.6};
  q.to = {2.0, 0.9};
  const ShotPlan middle = PlanShotForRobot(q, params_, {}, gantry_);
  ASSERT_EQ(middle.status, PlanStatus::kOk) << middle.reason;
  EXPECT_EQ(middle.stroke.elevation, 0.0);
}

}  // namespace
}  // namespace billiard::planner
