// Newton's method on the launch speed: its root, the isotropy it rests on, and its corrections
// from the closed form's launch.
#include "planner/newton_aim.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/testing/held_shot.h"

namespace billiard::planner {
namespace {

TEST(QuadraticRoot, IsTheRootNearestZero) {
  struct Case {
    double f, b, c;
  };
  for (const Case& k :
       {Case{-2.0, 3.0, 0.5}, Case{1.5, 2.0, -0.4}, Case{-0.3, 1.0, -0.2}, Case{0.7, 4.0, 0.1}}) {
    const double x = QuadraticRoot(k.f, k.b, k.c);
    EXPECT_NEAR(k.f + k.b * x + k.c * x * x, 0.0, 1e-12) << k.f << " " << k.b << " " << k.c;
    // The other root, -b / c - x, lies further from zero.
    EXPECT_LT(std::abs(x), std::abs(-k.b / k.c - x));
  }
  EXPECT_DOUBLE_EQ(QuadraticRoot(-2.0, 4.0, 0.0), 0.5) << "a line: Newton's step";
  EXPECT_DOUBLE_EQ(QuadraticRoot(1.0, 1.0, 1.0), -1.0) << "no root: Newton's step";
}

using testing::HeldShot;
using testing::Paper;

// The premise of the aim: turning the heading turns the whole path about the ball, so the reach
// and the turn of a run do not depend on its heading.
TEST(ReachOf, DoesNotDependOnTheHeading) {
  HeldShot p({1.2, 0.6}, {2.0, 0.9}, 0.2, SpinStyle::kDraw, 18.0);
  Shot shot(p.q, p.held, Paper(), p.options);
  const double speed = p.held.speed;
  const Reach a = ReachOf(shot.Arrive(speed, 0.3, false), p.q.from, 0.3);
  const Reach b = ReachOf(shot.Arrive(speed, 2.5, false), p.q.from, 2.5);
  EXPECT_GT(std::abs(a.turn), 1e-3) << "side spin curves the path";
  EXPECT_NEAR(a.reach, b.reach, 1e-9);
  EXPECT_NEAR(a.turn, b.turn, 1e-9);
}

TEST(Aim, ReachesTheToleranceInTwoCorrectionsWithOneRunWithSensitivities) {
  for (HeldShot p : {HeldShot({0.3, 0.4}, {1.9, 0.9}, 0.0, SpinStyle::kStun, 0.0),
                     HeldShot({0.5, 0.3}, {1.7, 1.0}, 0.2, SpinStyle::kDraw, 12.0)}) {
    Shot shot(p.q, p.held, Paper(), p.options);
    double launch[2] = {p.held.speed, p.held.heading};
    const int steps = Aim(shot, launch);
    EXPECT_GE(steps, 1);
    EXPECT_LE(steps, 2);
    EXPECT_TRUE(shot.Close(launch));
    EXPECT_EQ(shot.simulations(), steps + 1);
  }
}

TEST(Aim, StopsWhereItsStepLeavesTheSpeedBounds) {
  HeldShot p({0.3, 0.4}, {1.9, 0.9}, 0.0, SpinStyle::kStun, 0.0);
  p.held.speeds = {p.held.speed, p.held.speed};  // the closed form's launch, centimetres off
  Shot shot(p.q, p.held, Paper(), p.options);
  double launch[2] = {p.held.speed, p.held.heading};
  EXPECT_EQ(Aim(shot, launch), 0);
  EXPECT_EQ(launch[0], p.held.speed);
  EXPECT_EQ(launch[1], p.held.heading);
  EXPECT_EQ(shot.simulations(), 1);
}

}  // namespace
}  // namespace billiard::planner
