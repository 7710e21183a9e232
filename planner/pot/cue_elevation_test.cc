#include "planner/pot/cue_elevation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/testing/pot_fixture.h"
#include "sim/params/robots.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class CueElevationTest : public testing::PotFixture {
 protected:
  // A straight pot up the table's middle into upper_middle with the cue ball `gap` [m] off the
  // lower rail's nose: a level cue lies across the rail.
  std::vector<SceneBall> OffTheRail(double gap) const {
    const double x = table_.length / 2, r = params_.ball.radius;
    return {table::AtRest(0, x, r + gap), table::AtRest(1, x, table_.width / 2)};
  }
  PotRequest UpperMiddle() const { return PotRequest{1, "upper_middle", ShotKind::kDirect, std::nullopt}; }
  PotOptions WithGantry() const {
    PotOptions o;
    o.robot = params::LoadRobot("gantry");
    return o;
  }
};

// A centre hit's impulse along the cue (Alciatore 2004, TP A.30 with no offset):
// J = (1 + e) M m V / (m + M); its vertical part J sin(elevation) / m drives the ball down, and
// the bed returns kBedRestitution of it: the hop is (e_t J sin(elevation) / m)^2 / (2 g).
TEST_F(CueElevationTest, TheHopIsTheBedsReturnOfTheCuesDownwardImpulse) {
  const physics::CueStroke level{2.0, 0.3, 0.0, 0.0, 0.0};
  EXPECT_EQ(HopHeight(level, {1.0, 0.6}, params_), 0.0);
  const double elevation = 12.0 * kDegree, V = 2.0;
  const double m = params_.ball.mass, M = params_.cue.mass, e = params_.cue.tip_restitution;
  const double j = (1 + e) * M * m * V / (m + M);
  const double up = kBedRestitution * j * std::sin(elevation) / m;
  EXPECT_NEAR(HopHeight({V, 0.3, 0.0, 0.0, elevation}, {1.0, 0.6}, params_), up * up / (2 * params_.ball.gravity),
              1e-12);
}

// Off the rail the level cue is blocked; the plan rises to the least clearing elevation and its
// margin, clears, and still pots on `simulate --scene`'s motion.
TEST_F(CueElevationTest, APotOffTheRailIsPlayedAboveItAndStillPots) {
  const std::vector<SceneBall> balls = OffTheRail(0.1);
  const PotOptions options = WithGantry();
  const PotPlan plan = PlanPot(table_, params_, balls, UpperMiddle(), options);
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  physics::CueStroke level = plan.stroke;
  level.elevation = 0.0;
  EXPECT_FALSE(cue::Clearance(table_, params_.ball.radius, balls, 0, level, *options.robot).clears);
  const cue::ClearingElevation least =
      cue::LeastClearingElevation(table_, params_.ball.radius, balls, 0, plan.stroke, *options.robot);
  ASSERT_TRUE(least.elevation);
  EXPECT_NEAR(plan.stroke.elevation, *least.elevation + kElevationMargin, 0.2 * kDegree);
  ASSERT_TRUE(plan.clearance);
  EXPECT_TRUE(plan.clearance->clears);
  EXPECT_GT(plan.clearance->distance, 0.0);
  const Outcome o = Simulate(balls, plan.v0, plan.w0, 1, "upper_middle");
  EXPECT_TRUE(o.potted && o.first_contact == 1 && !o.scratch);
  EXPECT_TRUE(PlayStroke(table_, params_, balls, 1, "upper_middle", plan.stroke).legal);
}

// Without a robot the cue is not checked: the same pot is played level, as before robots.
TEST_F(CueElevationTest, WithoutARobotTheStrokeIsLevel) {
  const PotPlan plan = PlanPot(table_, params_, OffTheRail(0.1), UpperMiddle());
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  EXPECT_EQ(plan.stroke.elevation, 0.0);
  EXPECT_FALSE(plan.clearance);
}

// A robot that cannot raise its cue past 5 degrees clears the rail at no elevation: cue_blocked,
// and the reason says what blocks.
TEST_F(CueElevationTest, NothingInRangeClearsIsCueBlocked) {
  PotOptions options = WithGantry();
  options.robot->elevation.max = 5.0 * kDegree;
  const PotPlan plan = PlanPot(table_, params_, OffTheRail(0.1), UpperMiddle(), options);
  EXPECT_EQ(plan.status, PotStatus::kCueBlocked);
  EXPECT_STREQ(PotStatusName(plan.status), "cue_blocked");
  EXPECT_NE(plan.reason.find("rail"), std::string::npos) << plan.reason;
}

// A pot whose cue needs a steep elevation at the plan's pace would lift the ball: refused with
// the hop in the reason, not played as if it stayed on the cloth. 3 mm off the rail the gantry's
// cue needs 31 degrees, and the ball would hop 9 mm.
TEST_F(CueElevationTest, AStrokeThatWouldLiftTheBallIsRefused) {
  const PotPlan plan = PlanPot(table_, params_, OffTheRail(0.003), UpperMiddle(), WithGantry());
  ASSERT_EQ(plan.status, PotStatus::kNoStroke);
  EXPECT_NE(plan.reason.find("lift the ball off the cloth"), std::string::npos) << plan.reason;
}

}  // namespace
}  // namespace billiard::pot
