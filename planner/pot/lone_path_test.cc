#include "planner/pot/lone_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "planner/pot/cue_elevation.h"
#include "planner/pot/drop_window.h"
#include "planner/pot/pot_geometry.h"
#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class LonePathTest : public testing::PotFixture {
 protected:
  // The closest the cue ball, struck with `stroke` alone on the table, comes to `point` after
  // its first cushion (or from the start), sampled every 0.1 ms.
  double ClosestApproach(const physics::CueStroke& stroke, const Eigen::Vector2d& from, const Eigen::Vector2d& point,
                         bool after_rail) const {
    table::TableSimulation sim(table_, params_, {table::Struck(0, stroke, from, params_)}, {});
    sim.Run();
    double start = 0.0;
    if (after_rail) {
      for (const table::TableEvent& e : sim.events()) {
        if (e.type == table::EventType::kBallCushion) {
          start = e.time;
          break;
        }
      }
    }
    double closest = std::numeric_limits<double>::infinity();
    for (double t = start; t <= sim.time(); t += 1e-4) {
      closest = std::min(closest, (sim.StateAt(0, t).head<2>() - point).norm());
    }
    return closest;
  }
};

// A ball sent along +x passes a point 5 cm to its left at +5 cm, one to its right at -5 cm (to
// the path's sampling: every 2 ms, 3 mm of travel, puts the closest sample within 3e-5 m).
TEST_F(LonePathTest, APathPassesAPointOnItsLeftAtAPositiveDistance) {
  SearchContext search = Search({table::AtRest(0, 0.5, 0.6), table::AtRest(1, 2.0, 1.0)}, 1, "upper_right");
  const physics::CueStroke stroke{1.5, 0.0, 0.0, 0.0, 0.0};
  EXPECT_NEAR(PassingSide(search, stroke, {1.2, 0.65}, false), 0.05, 3e-5);
  EXPECT_NEAR(PassingSide(search, stroke, {1.2, 0.55}, false), -0.05, 3e-5);
  const Passing pass =
      Pass(search, table::Struck(0, stroke, {0.5, 0.6}, params_), {1.2, 0.65}, false);
  EXPECT_GT(pass.velocity.x(), 0.0);
  EXPECT_NEAR(pass.velocity.y(), 0.0, 1e-12);
  // A path that meets no cushion never passes anything after one.
  EXPECT_TRUE(std::isinf(PassingSide(search, physics::CueStroke{0.3, 0.0, 0.0, 0.0, 0.0}, {1.2, 0.65}, true)));
}

// A direct route's heading is the line to the ghost ball, less the squirt of the side spin.
TEST_F(LonePathTest, ADirectHeadingIsTheGhostBallsLineLessTheSquirt) {
  SearchContext search = Search({table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9)}, 1, "upper_right");
  const Eigen::Vector2d ghost(1.75, 0.88);
  const double line = Angle(ghost - Eigen::Vector2d(0.6, 0.6));
  Route route{ShotKind::kDirect, -1, search.pocket().centre, ghost};
  EXPECT_EQ(FirstHeading(search, route, {1.5, 0.0, 0.0, 0.0}, ghost), line);
  route.tip_side = 0.01;
  EXPECT_EQ(FirstHeading(search, route, {1.5, 0.01, 0.0, 0.0}, ghost), line - physics::SquirtAngle(0.01, params_));
  EXPECT_EQ(search.simulations(), 0) << "geometry alone";
}

// A kick's heading is found on the cue ball's own path: after its rail it passes through the
// ghost ball (to the path's sampling, 2 ms of travel), which the mirror's heading (the ideal
// reflection, degrees off the cushion model's rebound) does not.
TEST_F(LonePathTest, AKicksHeadingSendsTheCueBallThroughTheGhostBallAfterItsRail) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.5, 0.4), table::AtRest(1, 1.6, 0.7), table::AtRest(2, 1.1, 0.55)};
  SearchContext search = Search(balls, 1, "upper_right");
  search.SearchAmong({}, true);  // a kick's rail is met as the truth meets it
  const std::vector<Candidate> kicks = Routes(search, ShotKind::kKick);
  ASSERT_FALSE(kicks.empty());
  const Route& route = kicks.front().route;
  const Eigen::Vector2d k(1.6, 0.7);
  const Eigen::Vector2d ghost = GhostBall(k, (route.object_aim - k).normalized(), params_.ball.radius);
  const StrokeShape shape{1.5, 0.0, 0.0, 0.0};
  const double heading = FirstHeading(search, route, shape, ghost);
  const double mirror = Angle(route.cue_aim - search.cue_position());
  EXPECT_LT(ClosestApproach(shape.At(heading), search.cue_position(), ghost, true), 2e-3);
  EXPECT_GT(ClosestApproach(shape.At(mirror), search.cue_position(), ghost, true), 1e-2);
}

// A curve's heading bends the cue ball's path (an elevated cue with side spin) through the ghost
// ball (to the path's sampling, 2 ms of travel); the straight line's heading bends it past.
TEST_F(LonePathTest, ACurvesHeadingBendsTheCueBallThroughTheGhostBall) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.7), table::AtRest(3, 1.6, 0.7), table::AtRest(6, 1.1, 0.735)};
  SearchContext search = Search(balls, 3, "upper_right");
  const Route route = Routes(search, ShotKind::kCurve).front().route;
  // At its pace, the fastest whose hop the table's motion covers (pace.h).
  StrokeShape shape{0.0, route.tip_side, route.tip_height, route.elevation};
  shape.speed = TopCueSpeed(search, shape, Angle(route.cue_aim - search.cue_position()));
  const double heading = FirstHeading(search, route, shape, route.cue_aim);
  const double straight = Angle(route.cue_aim - search.cue_position());
  // The path is sampled every 2 ms: its closest sample lies within a millisecond's travel at the
  // launch speed (the fastest the ball goes) of where it passes.
  const double launch = physics::StrikeBall(shape.At(heading), search.cue_position(), params_)
                            .segment<2>(physics::kVx)
                            .norm();
  EXPECT_LT(ClosestApproach(shape.At(heading), search.cue_position(), route.cue_aim, false),
            launch * 1e-3);
  EXPECT_GT(ClosestApproach(shape.At(straight), search.cue_position(), route.cue_aim, false), 1e-2);
}

// The pocket behind the object ball: no curve within the cue's elevations bends the cue ball
// round to a cut below the limit, which its path alone shows where it passes the ghost ball.
TEST_F(LonePathTest, ABackwardsCurveIsTooThin) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9)};
  const PotPlan plan = PlanPot(table_, params_, balls, {1, "lower_left", ShotKind::kCurve, {}});
  EXPECT_EQ(plan.status, PotStatus::kTooThin) << plan.reason;
  EXPECT_NE(plan.reason.find("curve: the curve's cut is"), std::string::npos) << plan.reason;
}

// A bank's line is found on K's own path off the rail: it passes the pocket's mouth.
TEST_F(LonePathTest, ABanksLinePassesThePocketsMouthAfterTheRail) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.5), table::AtRest(1, 1.3, 0.4)};
  SearchContext search = Search(balls, 1, "upper_right");
  const std::vector<Candidate> banks = Routes(search, ShotKind::kBank);
  ASSERT_FALSE(banks.empty());
  const Route& route = banks.front().route;
  search.SearchAmong({}, true);
  const Eigen::Vector2d k(1.3, 0.4);
  const double mirror = Angle(route.object_aim - k);
  const Contact c = search.FirstContact({2.0, Angle(k - search.cue_position()), 0.0, 0.0, 0.0}, false);
  ASSERT_EQ(c.ball, 1);
  const double line = BankLine(search, c, mirror);
  physics::BallState sent = Rotated(c.object_after, Wrap(line - c.departure));
  sent.tail<5>() *= ReachScale(c);
  EXPECT_LT(std::abs(PassingSide(search, sent, search.pocket().centre, true)), 1e-3);
  EXPECT_LT(std::abs(Wrap(line - mirror)), 8.0 * kDegree);
}

}  // namespace
}  // namespace billiard::pot
