#include "planner/pot/cue_elevation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "planner/pot/testing/pot_fixture.h"
#include "sim/params/robots.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class CueElevationTest : public testing::PotFixture {
 protected:
  // A straight pot up the table's middle into upper_middle with the cue ball `gap` [m] off the
  // lower rail's nose (a level cue lies across the rail) and ball 1 at the table's middle, or
  // `ahead` [m] in front of the cue ball.
  std::vector<SceneBall> OffTheRail(double gap, std::optional<double> ahead = std::nullopt) const {
    const double x = table_.length / 2, r = params_.ball.radius;
    const double object = ahead ? r + gap + *ahead : table_.width / 2;
    return {table::AtRest(0, x, r + gap), table::AtRest(1, x, object)};
  }
  PotRequest UpperMiddle() const { return PotRequest{1, "upper_middle", ShotKind::kDirect, std::nullopt}; }
  PotOptions WithGantry() const {
    PotOptions o;
    o.robot = params::LoadRobot("gantry");
    return o;
  }
};

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
  EXPECT_NEAR(plan.stroke.elevation, *least.elevation + cue::kElevationMargin, 0.2 * kDegree);
  ASSERT_TRUE(plan.clearance);
  EXPECT_TRUE(plan.clearance->clears);
  EXPECT_GT(plan.clearance->distance, 0.0);
  const Outcome o = SimulatePlan(balls, plan);
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

// A pot whose cue needs a steep elevation is paced within the hop the table's motion covers
// (cue::TableMaxHop), not played as if the ball stayed down: 3 mm off the rail the gantry's cue
// needs 31 degrees, at which a 0.7 m/s cue is the fastest that does not hop the ball beyond the
// limit, too slow to send ball 1 from 30 cm in front of the cue ball to the far rail's pocket
// (from 10 cm it reaches it): refused, with that pace and that elevation in the reason (what
// tells a steep cue from a long pot).
TEST_F(CueElevationTest, AStrokeThatWouldLiftTheBallIsPacedBelowTheHopOrRefused) {
  const PotPlan plan =
      PlanPot(table_, params_, OffTheRail(0.003, 0.3), UpperMiddle(), WithGantry());
  ASSERT_EQ(plan.status, PotStatus::kNoStroke);
  const std::string said =
      "the fastest stroke whose hop the table's motion covers with the cue at ";
  const std::size_t at = plan.reason.find(said);
  ASSERT_NE(at, std::string::npos) << plan.reason;
  const double elevation_deg = std::stod(plan.reason.substr(at + said.size()));
  EXPECT_GT(elevation_deg, 25.0) << plan.reason;
  EXPECT_LT(elevation_deg, 40.0) << plan.reason;
}

// Every plan's stroke hops the ball within what the table's motion covers: off the rail at gaps
// where the cue must rise, the planned pots hop the ball no more than the limit.
TEST_F(CueElevationTest, EveryPlannedStrokeHopsTheBallWithinTheLimit) {
  int raised = 0;
  for (const double gap : {0.005, 0.01, 0.02, 0.05, 0.1}) {
    const std::vector<SceneBall> balls = OffTheRail(gap);
    const PotPlan plan = PlanPot(table_, params_, balls, UpperMiddle(), WithGantry());
    if (plan.status != PotStatus::kOk) continue;
    raised += plan.stroke.elevation > 0.0;
    EXPECT_LE(cue::HopHeight(plan.stroke, Eigen::Vector2d(balls[0].state.head<2>()), params_),
              cue::TableMaxHop(params_) * (1 + 1e-9))
        << "gap " << gap;
  }
  EXPECT_GE(raised, 2);
}

}  // namespace
}  // namespace billiard::pot
