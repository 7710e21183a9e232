// The playing surface, and the requests a speed bound decides without a refinement.
#include "planner/reachability.h"

#include <gtest/gtest.h>

#include "planner/testing/held_shot.h"

namespace billiard::planner {
namespace {

using testing::HeldShot;
using testing::Paper;

TEST(OnTable, IsARadiusInsideEveryEdge) {
  const double r = Paper().ball.radius, length = Paper().table.length, width = Paper().table.width;
  EXPECT_TRUE(OnTable({r, r}, Paper()));
  EXPECT_TRUE(OnTable({length - r, width - r}, Paper()));
  EXPECT_TRUE(OnTable({0.5 * length, 0.5 * width}, Paper()));
  for (const Eigen::Vector2d& x :
       {Eigen::Vector2d(0.99 * r, 0.5), Eigen::Vector2d(1.0, 0.99 * r),
        Eigen::Vector2d(length - 0.99 * r, 0.5), Eigen::Vector2d(1.0, width - 0.99 * r)}) {
    EXPECT_FALSE(OnTable(x, Paper())) << x.transpose();
  }
}

TEST(NoStrokeGivesTheSpin, NamesTheSpinAndTheRobotsLimits) {
  ShotRequest q;
  q.side_spin = 3000.0;
  const std::string reason = NoStrokeGivesTheSpin(-1.0, q, Paper());
  EXPECT_NE(reason.find("R w / v = -1"), std::string::npos) << reason;
  EXPECT_NE(reason.find("wz = 3e+03"), std::string::npos) << reason;
  EXPECT_NE(reason.find("m/s"), std::string::npos) << reason;
}

// A natural roll 1 m along the table, its speeds bounded as the test says.
HeldShot Roll() { return HeldShot({0.5, 0.6}, {1.5, 0.6}); }

TEST(BeyondReach, WithinTheBoundsNothingIsDecidedOrSimulated) {
  HeldShot roll = Roll();
  Shot shot(roll.q, roll.held, Paper(), roll.options);
  EXPECT_FALSE(BeyondReach(shot, roll.held.speed, roll.held.heading));
  EXPECT_EQ(shot.simulations(), 0);
}

TEST(BeyondReach, TheFastestLaunchShortOfTheTargetIsOutOfReach) {
  HeldShot roll = Roll();
  roll.held.speeds.max = 0.5 * roll.held.speed;  // a quarter of the energy: a quarter of the way
  Shot shot(roll.q, roll.held, Paper(), roll.options);
  const auto reason = BeyondReach(shot, roll.held.speeds.max, roll.held.heading);
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("faster launch"), std::string::npos) << *reason;
  EXPECT_EQ(shot.simulations(), 1);
}

TEST(BeyondReach, TheSlowestLaunchPastTheTargetIsOutOfReach) {
  HeldShot roll = Roll();
  roll.held.speeds.min = 1.5 * roll.held.speed;
  Shot shot(roll.q, roll.held, Paper(), roll.options);
  const auto reason = BeyondReach(shot, roll.held.speed, roll.held.heading);
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("past the target"), std::string::npos) << *reason;
}

TEST(BeyondReach, ABoundThatReachesTheTargetDecidesNothing) {
  HeldShot roll = Roll();
  roll.held.speeds.max = roll.held.speed;  // the closed form's natural roll: within millimetres
  roll.options.acceptable_miss = 0.05;
  Shot shot(roll.q, roll.held, Paper(), roll.options);
  EXPECT_FALSE(BeyondReach(shot, roll.held.speed, roll.held.heading));
  EXPECT_EQ(shot.simulations(), 1);
}

}  // namespace
}  // namespace billiard::planner
