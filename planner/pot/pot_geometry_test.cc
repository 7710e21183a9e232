#include "planner/pot/pot_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/table_specs.h"

namespace billiard::pot {
namespace {

constexpr double kR = 0.028575;

TEST(PotGeometry, GhostBallTouchesTheObjectBallBehindItsLine) {
  const Eigen::Vector2d k(1.0, 0.5);
  const Eigen::Vector2d u = Eigen::Vector2d(3.0, 4.0).normalized();
  const Eigen::Vector2d g = GhostBall(k, u, kR);
  EXPECT_NEAR((g - k).norm(), 2.0 * kR, 1e-15);
  EXPECT_NEAR((k - g).normalized().dot(u), 1.0, 1e-15);
}

TEST(PotGeometry, CutAngleIsTheAngleBetweenApproachAndDeparture) {
  EXPECT_NEAR(CutAngle({1, 0}, {1, 0}), 0.0, 1e-12);
  EXPECT_NEAR(CutAngle({1, 0}, {0, 1}), M_PI / 2, 1e-12);
  EXPECT_NEAR(CutAngle({1, 0}, Eigen::Vector2d(1, 1).normalized()), M_PI / 4, 1e-12);
}

TEST(PotGeometry, ARailBounceReflectsAboutTheOffsetLine) {
  const table::TableGeometry t = table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  ASSERT_EQ(RailCount(t), 6);
  // Off the lower rail (y = 0) whichever segment holds the bounce: equal angles either side.
  const Eigen::Vector2d from(0.6, 0.5), to(1.0, 0.3);
  for (int rail = 0; rail < RailCount(t); ++rail) {
    const auto b = RailBounce(t, rail, from, to, kR);
    if (!b || std::abs(t.lines[rail].normal.y() - 1.0) > 1e-12) continue;
    EXPECT_NEAR(b->y(), kR, 1e-12);
    const Eigen::Vector2d in = (*b - from).normalized(), out = (to - *b).normalized();
    EXPECT_NEAR(in.x(), out.x(), 1e-12);
    EXPECT_NEAR(in.y(), -out.y(), 1e-12);
    return;
  }
  FAIL() << "no lower rail holds the bounce";
}

TEST(PotGeometry, BallsAcrossALineAreThoseWithinTheClearance) {
  std::vector<table::SceneBall> balls = {
      {0, physics::MakeBallState(0, 0, 0, 0, 0, 0, 0)},
      {1, physics::MakeBallState(1, 0.05, 0, 0, 0, 0, 0)},
      {2, physics::MakeBallState(1, 0.06, 0, 0, 0, 0, 0)},
      {3, physics::MakeBallState(2.1, 0, 0, 0, 0, 0, 0)}};
  // Ball 1 is 5 cm off the line, within 2R = 5.7 cm; ball 2 is 6 cm off; ball 3 beyond the end.
  EXPECT_EQ(BallsAcross(balls, {0, 0}, {2, 0}, 2 * kR, {0}), (std::vector<int>{1}));
}

}  // namespace
}  // namespace billiard::pot
