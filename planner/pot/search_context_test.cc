#include "planner/pot/search_context.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/pot/testing/pot_fixture.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class SearchContextTest : public testing::PotFixture {};

TEST(SearchAngles, WrapUnitAndAngleAgree) {
  EXPECT_NEAR(Wrap(3.0 * M_PI / 2.0), -M_PI / 2.0, 1e-15);
  EXPECT_NEAR(Wrap(-0.25), -0.25, 1e-15);
  EXPECT_NEAR(Angle(Unit(2.5)), 2.5, 1e-15);
  EXPECT_NEAR(Unit(M_PI / 3.0).norm(), 1.0, 1e-15);
}

// Turning a state turns its velocity and horizontal spin alike, and keeps the rest.
TEST(SearchAngles, RotatedTurnsVelocityAndSpinAboutTheVertical) {
  const physics::BallState s = physics::MakeBallState(0.3, 0.4, 1.0, 0.0, 0.0, 20.0, 5.0);
  const physics::BallState t = Rotated(s, M_PI / 2.0);
  EXPECT_NEAR(t[physics::kVx], 0.0, 1e-15);
  EXPECT_NEAR(t[physics::kVy], 1.0, 1e-15);
  EXPECT_NEAR(t[physics::kWx], -20.0, 1e-14);
  EXPECT_NEAR(t[physics::kWy], 0.0, 1e-14);
  EXPECT_EQ(t.head<2>(), s.head<2>());
  EXPECT_EQ(t[physics::kWz], s[physics::kWz]);
}

TEST_F(SearchContextTest, TheCueBallIsStruckFromRestWhereItLies) {
  std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6)};
  balls[0].state[physics::kVx] = 1.0;
  const SearchContext search = Search(balls, 1, "upper_right");
  EXPECT_EQ(search.cue_position(), Eigen::Vector2d(0.6, 0.6));
  EXPECT_EQ(search.cue_ball().state.tail<5>(), (Eigen::Matrix<double, 5, 1>::Zero()));
  EXPECT_EQ(search.object_ball().id, 1);
  EXPECT_EQ(search.simulations(), 0);
}

// A full-ball stroke along the line of centres meets K where the ghost ball is, and K leaves
// along that line: no cut, no throw.
TEST_F(SearchContextTest, AFullBallStrokeMeetsKAtTheGhostBall) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6), table::AtRest(2, 2.0, 1.0)};
  SearchContext search = Search(balls, 1, "upper_right");
  const Contact c = search.FirstContact({1.5, 0.0, 0.0, 0.0, 0.0}, false);
  ASSERT_EQ(c.ball, 1);
  const double r = params_.ball.radius;
  EXPECT_NEAR((c.cue_at - Eigen::Vector2d(1.6 - 2.0 * r, 0.6)).norm(), 0.0, 1e-9);
  EXPECT_NEAR(c.normal, 0.0, 1e-12);
  EXPECT_NEAR(c.departure, 0.0, 1e-12);
  ASSERT_EQ(c.others.size(), 1u);
  EXPECT_EQ(c.others.front().id, 2);
  EXPECT_EQ(search.simulations(), 1);
}

TEST_F(SearchContextTest, AStrokeThatMeetsNoBallHasNoContact) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.6, 0.6), table::AtRest(1, 1.6, 0.6)};
  SearchContext search = Search(balls, 1, "upper_right");
  EXPECT_EQ(search.FirstContact({1.0, M_PI / 2.0, 0.0, 0.0, 0.0}, false).ball, -1);
}

// Played until K's fate is decided, a straight-in pot stops as K drops, with the speed K had
// there. Played to rest it goes on: the cue ball, rolling at contact, keeps some of its speed and
// follows K in, a scratch that the stroke played until K drops cannot tell.
TEST_F(SearchContextTest, APotPlayedUntilKDropsStopsThere) {
  const Eigen::Vector2d corner = table_.PocketNamed("lower_left")->centre;
  const Eigen::Vector2d along = Eigen::Vector2d(1.0, 1.0).normalized();
  const Eigen::Vector2d k = corner + 0.6 * along, cue = corner + 1.2 * along;
  const std::vector<SceneBall> balls = {table::AtRest(0, cue.x(), cue.y()), table::AtRest(3, k.x(), k.y())};
  SearchContext search = Search(balls, 3, "lower_left");
  const physics::CueStroke stroke{1.5, Angle(-along), 0.0, 0.0, 0.0};
  const Played until = search.Play(stroke, false, false);
  const Played rest = search.Play(stroke, false, true);
  for (const Played* p : {&until, &rest}) {
    EXPECT_TRUE(p->outcome.potted);
    EXPECT_EQ(p->outcome.first_contact, 3);
    ASSERT_TRUE(p->arrival_speed);
    EXPECT_GT(*p->arrival_speed, 0.0);
  }
  EXPECT_EQ(*until.arrival_speed, *rest.arrival_speed);
  EXPECT_EQ(until.sim->events().back().type, table::EventType::kBallPocket);
  EXPECT_LT(until.sim->time(), rest.sim->time());
  EXPECT_TRUE(until.outcome.legal);
  EXPECT_TRUE(rest.sim->AtRest());
  EXPECT_EQ(rest.outcome.cue_pocket, std::optional<std::string>("lower_left"));
  EXPECT_FALSE(rest.outcome.legal);
  EXPECT_EQ(search.simulations(), 2);
}

}  // namespace
}  // namespace billiard::pot
