#include "planner/pot/aim.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/pot_geometry.h"
#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class AimTest : public testing::PotFixture {};

// Full ball, the cue ball sliding without spin onto K at rest: nothing turns K off the line of
// centres, so the normal that sends it along a direction is that direction.
TEST_F(AimTest, AFullBallWithoutSpinHasNoThrow) {
  const double r = params_.ball.radius;
  for (double target : {0.0, 0.7, -2.0}) {
    Contact c;
    c.object_at = Eigen::Vector2d(1.5, 0.7);
    const Eigen::Vector2d cue = c.object_at - 2.0 * r * Unit(target);
    const Eigen::Vector2d v = 1.2 * Unit(target);
    c.cue_before = physics::MakeBallState(cue.x(), cue.y(), v.x(), v.y(), 0, 0, 0);
    c.object_before = physics::MakeBallState(c.object_at.x(), c.object_at.y(), 0, 0, 0, 0, 0);
    EXPECT_NEAR(Wrap(ThrowCorrectedNormal(params_, c, target) - target), 0.0, 1e-12) << target;
  }
}

// A cut throws K off the line of centres toward the cue ball's travel (Alciatore TP A.14): the
// normal that sends it along the target lies beyond the target, away from that travel.
TEST_F(AimTest, ACutsNormalIsTurnedAgainstTheThrow) {
  const double r = params_.ball.radius;
  const double target = 0.6;  // K's departure; the cue ball travels along +x, a 34 degree cut
  Contact c;
  c.object_at = Eigen::Vector2d(1.5, 0.7);
  const Eigen::Vector2d cue = c.object_at - 2.0 * r * Unit(target);
  c.cue_before = physics::MakeBallState(cue.x(), cue.y(), 1.0, 0, 0, 0, 0);
  c.object_before = physics::MakeBallState(c.object_at.x(), c.object_at.y(), 0, 0, 0, 0, 0);
  const double normal = ThrowCorrectedNormal(params_, c, target);
  EXPECT_GT(normal - target, 0.2 * kDegree);
  EXPECT_LT(normal - target, 6.0 * kDegree);
}

// A straight shot aimed at K's line to the pocket: it meets K full, at the ghost ball, and K
// leaves along the line.
TEST_F(AimTest, TheAimOfAStraightShotMeetsTheGhostBall) {
  const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = Eigen::Vector2d(1.0, 1.0).normalized();
  const Eigen::Vector2d k = corner + 0.6 * along, cue = corner + 1.2 * along;
  SearchContext search = Search({table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, k.x(), k.y())}, 3, "lower_left");
  const double line = Angle(-along);
  const std::optional<Aimed> aimed = AimAt(search, {1.5, 0.0, 0.0, 0.0}, line + 0.5 * kDegree, line, false, 0.0);
  ASSERT_TRUE(aimed);
  EXPECT_NEAR(Wrap(aimed->heading - line), 0.0, kAimAccepted);
  EXPECT_NEAR(Wrap(aimed->contact.departure - line), 0.0, kAimTolerance);
  EXPECT_NEAR(Wrap(aimed->contact.normal - line), 0.0, kAimTolerance);
  EXPECT_NEAR((aimed->contact.cue_at - GhostBall(k, -along, params_.ball.radius)).norm(), 0.0, 1e-4);
}

// A first guess that misses K by a degree: the headings either side are tried until one meets it.
TEST_F(AimTest, AFirstGuessThatMissesKIsMovedUntilItMeetsK) {
  SearchContext search = Search({table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6)}, 1, "upper_right");
  const double edge = std::asin(2.0 * params_.ball.radius / 1.0);  // the thinnest touch
  const double target = -1.0;  // a cut of 57 degrees: K leaves to the right of the cue ball
  const std::optional<Aimed> aimed = AimAt(search, {1.5, 0.0, 0.0, 0.0}, edge + 1.0 * kDegree, target, false, 0.0);
  ASSERT_TRUE(aimed);
  EXPECT_EQ(aimed->contact.ball, 1);
  EXPECT_NEAR(Wrap(aimed->contact.departure - target), 0.0, kAimAccepted);
  EXPECT_EQ(BlockedReason(search, {1.5, 0.0, 0.0, 0.0}, edge + 1.0 * kDegree), "no heading near the route meets ball 1");
}

TEST_F(AimTest, ABlockedAimNamesTheBallMetFirst) {
  SearchContext search = Search({table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6), table::AtRest(2, 1.1, 0.6)}, 1, "upper_right");
  EXPECT_FALSE(AimAt(search, {1.5, 0.0, 0.0, 0.0}, 0.0, 0.0, false, 0.0));
  EXPECT_EQ(BlockedReason(search, {1.5, 0.0, 0.0, 0.0}, 0.0), "the cue ball meets ball 2 before ball 1");
}

// Cut-induced throw (Alciatore, TP A.14): the object ball leaves between the line of centres and
// the cue ball's travel, a few degrees off the line for a slow cut. Aimed through the ghost ball
// alone (the line of centres on the window's middle) it departs off the middle by the throw; the
// plan's aim departs on it.
TEST_F(AimTest, TheAimCorrectsTheThrowThatTheGhostBallAloneLeaves) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 1.5, 0.2), table::AtRest(4, 1.7, 0.75)};
  const PotPlan plan = PlanPot(table_, params_, balls, {4, "upper_right", ShotKind::kDirect, {}});
  ASSERT_EQ(plan.status, PotStatus::kOk) << plan.reason;
  const std::optional<double> heading = GhostBallHeading(table_, params_, balls, plan);
  ASSERT_TRUE(heading);
  ASSERT_GT(plan.cut_deg, 20.0);
  physics::CueStroke ghost = plan.stroke;
  ghost.heading = *heading;
  const Outcome aimed = SimulateStroke(balls, plan.stroke, plan.ball, plan.pocket);
  const Outcome naive = SimulateStroke(balls, ghost, plan.ball, plan.pocket);
  const double throw_deg = std::remainder(naive.departure - naive.normal, 2 * M_PI) / kDegree;
  const double cue_side = std::remainder(ghost.heading - naive.normal, 2 * M_PI);
  EXPECT_GT(std::abs(throw_deg), 0.5);
  EXPECT_LT(std::abs(throw_deg), 6.0);
  EXPECT_GT(throw_deg * cue_side, 0.0) << "thrown toward the cue ball's travel";
  // The plan departs along its departure, where the ghost ball's line of centres points.
  EXPECT_NEAR(std::remainder(naive.normal - plan.departure, 2 * M_PI), 0.0, 1e-5);
  EXPECT_NEAR(std::remainder(aimed.departure - plan.departure, 2 * M_PI), 0.0, 1e-5);
}

}  // namespace
}  // namespace billiard::pot
