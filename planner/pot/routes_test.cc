#include "planner/pot/routes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "planner/pot/pot_geometry.h"
#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class RoutesTest : public testing::PotFixture {
 protected:
  // The route's path: the cue ball's start, its aim, the ghost ball, K, its aim, the pocket.
  double Length(const SearchContext& search, const Route& route) const {
    const Eigen::Vector2d k = search.object_ball().state.head<2>();
    const Eigen::Vector2d ghost = GhostBall(k, (route.object_aim - k).normalized(), params_.ball.radius);
    return (route.cue_aim - search.cue_position()).norm() + (ghost - route.cue_aim).norm() +
           (route.object_aim - k).norm() + (search.pocket().centre - route.object_aim).norm();
  }

  // `aim` is a mirror's bounce from `from` to `to` off the rail: on the rail's offset line, the
  // path along the rail unchanged and across it reversed.
  void ExpectMirrored(int rail, const Eigen::Vector2d& from, const Eigen::Vector2d& aim,
                      const Eigen::Vector2d& to) const {
    const table::CushionLine& line = table_.lines[static_cast<std::size_t>(rail)];
    EXPECT_NEAR((aim - line.a).dot(line.normal), params_.ball.radius, 1e-12);
    const Eigen::Vector2d in = (aim - from).normalized(), out = (to - aim).normalized();
    EXPECT_NEAR(in.dot(line.normal), -out.dot(line.normal), 1e-12);
    EXPECT_NEAR(in.dot(line.b - line.a), out.dot(line.b - line.a), 1e-12);
  }
};

TEST_F(RoutesTest, ADirectRouteAimsKAtThePocketAndTheCueBallAtTheGhostBall) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.8, 0.9)};
  const SearchContext search = Search(balls, 1, "upper_right");
  const std::vector<Candidate> routes = Routes(search, ShotKind::kDirect);
  ASSERT_EQ(routes.size(), 1u);
  const Route& route = routes.front().route;
  EXPECT_EQ(route.object_aim, search.pocket().centre);
  const Eigen::Vector2d k(1.8, 0.9);
  EXPECT_NEAR((route.cue_aim - k).norm(), 2.0 * params_.ball.radius, 1e-12);
  EXPECT_NEAR((k - route.cue_aim).normalized().dot((route.object_aim - k).normalized()), 1.0, 1e-12);
  EXPECT_TRUE(routes.front().blocked.empty());
}

TEST_F(RoutesTest, ABlockedLineNamesTheBallsAcrossIt) {
  // Ball 2 sits on the straight line from ball 1 to the lower right pocket.
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.5, 0.4), table::AtRest(1, 1.6, 0.7), table::AtRest(2, 2.05, 0.38)};
  const std::vector<Candidate> routes = Routes(Search(balls, 1, "lower_right"), ShotKind::kDirect);
  ASSERT_EQ(routes.size(), 1u);
  EXPECT_EQ(routes.front().blockers, std::vector<int>{2});
  EXPECT_EQ(routes.front().blocked, "ball 1's line to the pocket is blocked by ball 2");
}

// A bank sends K to the pocket's mirror image in the rail: its bounce is a mirror's, K's route
// to the bounce and on to the pocket the same angle either side of the rail's normal.
TEST_F(RoutesTest, ABanksRouteMirrorsInItsRail) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.5), table::AtRest(1, 1.3, 0.4)};
  const SearchContext search = Search(balls, 1, "upper_right");
  const std::vector<Candidate> banks = Routes(search, ShotKind::kBank);
  ASSERT_FALSE(banks.empty());
  for (const Candidate& c : banks) {
    SCOPED_TRACE(c.route.rail);
    EXPECT_EQ(c.route.kind, ShotKind::kBank);
    ExpectMirrored(c.route.rail, {1.3, 0.4}, c.route.object_aim, search.pocket().centre);
  }
}

// A kick sends the cue ball to the ghost ball's mirror image in the rail.
TEST_F(RoutesTest, AKicksRouteMirrorsTheGhostBallInItsRail) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.5, 0.4), table::AtRest(1, 1.6, 0.7), table::AtRest(2, 1.1, 0.55)};
  const SearchContext search = Search(balls, 1, "upper_right");
  const Eigen::Vector2d k(1.6, 0.7);
  const Eigen::Vector2d ghost = GhostBall(k, (search.pocket().centre - k).normalized(), params_.ball.radius);
  const std::vector<Candidate> kicks = Routes(search, ShotKind::kKick);
  ASSERT_FALSE(kicks.empty());
  for (const Candidate& c : kicks) {
    SCOPED_TRACE(c.route.rail);
    ExpectMirrored(c.route.rail, search.cue_position(), c.route.cue_aim, ghost);
  }
}

TEST_F(RoutesTest, RoutesComeShortestFirst) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.5), table::AtRest(1, 1.3, 0.4)};
  const SearchContext search = Search(balls, 1, "upper_right");
  for (ShotKind kind : {ShotKind::kBank, ShotKind::kKick}) {
    const std::vector<Candidate> routes = Routes(search, kind);
    ASSERT_GE(routes.size(), 2u) << ShotKindName(kind);
    for (std::size_t i = 1; i < routes.size(); ++i) {
      EXPECT_LE(Length(search, routes[i - 1].route), Length(search, routes[i].route)) << ShotKindName(kind);
    }
  }
}

// A curve bends away from the cue ball's line: a ball on it blocks no curve.
TEST_F(RoutesTest, CurvesAreTriedAtEachElevationAndSideWhateverIsOnTheCueBallsLine) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.7), table::AtRest(3, 1.6, 0.7), table::AtRest(6, 1.1, 0.735)};
  const std::vector<Candidate> curves = Routes(Search(balls, 3, "upper_right"), ShotKind::kCurve);
  ASSERT_EQ(curves.size(), 6u);
  for (const Candidate& c : curves) {
    EXPECT_TRUE(c.blocked.empty()) << c.blocked;
    EXPECT_GT(c.route.elevation, 0.0);
    EXPECT_NEAR(std::abs(c.route.tip_side), 0.7 * params_.cue.max_tip_offset * params_.ball.radius, 1e-15);
    EXPECT_NEAR(c.route.tip_height, -0.7 * params_.cue.max_tip_offset * params_.ball.radius, 1e-15);
  }
}

// The search's scene: the cue ball, K, and the balls within 15 cm of the routes' lines (beyond
// contact); one 30 cm off them is left to the truth.
TEST_F(RoutesTest, TheSearchSimulatesTheBallsNearTheRoutes) {
  const double r = params_.ball.radius;
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6), table::AtRest(2, 1.1, 0.6 + 2 * r + 0.1),
                                        table::AtRest(3, 1.1, 0.6 - 2 * r - 0.3)};
  const SearchContext search = Search(balls, 1, "lower_right");
  const std::vector<Candidate> routes = Routes(search, ShotKind::kDirect);
  ASSERT_EQ(routes.size(), 1u);
  std::vector<int> ids;
  for (const SceneBall& b : NearRoute(search, routes.front().route)) ids.push_back(b.id);
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace billiard::pot
