// The launch as speed and heading, and the shot's simulations: each launch run once, the miss and
// its Jacobian as the runs and their sensitivities say.
#include "planner/shot.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/testing/held_shot.h"

namespace billiard::planner {
namespace {

using testing::HeldShot;
using testing::Paper;

TEST(Launch, IsTheSpeedAlongTheHeadingWithTheSpinRatioAcrossTheLine) {
  const double radius = 0.028575, k = -0.7, side = 12.0, speed = 2.0, heading = 2.4;
  const Launch launch({0.5, 0.6}, k, side, radius);
  const physics::BallState s = launch.State(speed, heading);
  const Eigen::Vector2d e(std::cos(heading), std::sin(heading));
  EXPECT_DOUBLE_EQ(s[physics::kX], 0.5);
  EXPECT_DOUBLE_EQ(s[physics::kY], 0.6);
  const Eigen::Vector2d v = s.segment<2>(physics::kVx), w = s.segment<2>(physics::kWx);
  EXPECT_NEAR((v - speed * e).norm(), 0.0, 1e-15);
  // R w about z x e (topspin > 0) is k times the speed; none of it along the line.
  EXPECT_NEAR(radius * w.dot(Eigen::Vector2d(-e.y(), e.x())), k * speed, 1e-14);
  EXPECT_NEAR(w.dot(e), 0.0, 1e-14);
  EXPECT_EQ(s[physics::kWz], side);
}

TEST(Launch, DerivativeIsTheRateOfChangeOfTheState) {
  const Launch launch({1.0, 0.4}, 0.5, -8.0, 0.028575);
  const double speed = 1.3, heading = -0.9, h = 1e-6;
  const Eigen::Matrix<double, 7, 2> d = launch.Derivative(speed, heading);
  const Eigen::Matrix<double, 7, 1> by_speed =
      (launch.State(speed + h, heading) - launch.State(speed - h, heading)) / (2 * h);
  const Eigen::Matrix<double, 7, 1> by_heading =
      (launch.State(speed, heading + h) - launch.State(speed, heading - h)) / (2 * h);
  EXPECT_LT((d.col(0) - by_speed).norm(), 1e-7);
  EXPECT_LT((d.col(1) - by_heading).norm(), 1e-7);
}

// A follow shot with side spin, on the paper's table.
HeldShot FollowShot() { return HeldShot({0.4, 1.0}, {2.1, 0.3}, 0.3, SpinStyle::kFollow, -15.0); }

TEST(HoldTheSpin, StartsFromTheClosedFormsLaunchWithItsSpin) {
  const HeldShot f = FollowShot();
  ASSERT_TRUE(f.guess.ok) << f.guess.reason;
  EXPECT_DOUBLE_EQ(f.held.speed, f.guess.v0.norm());
  EXPECT_DOUBLE_EQ(f.held.spin_ratio, SpinRatio(SpinStyle::kFollow));
  EXPECT_LE(f.held.speeds.min, f.held.speed);
  EXPECT_GE(f.held.speeds.max, f.held.speed);
  // The launch it parametrises is the closed form's, to rounding.
  const physics::BallState s =
      Launch(f.q.from, f.held.spin_ratio, f.q.side_spin, Paper().ball.radius)
          .State(f.held.speed, f.held.heading);
  EXPECT_LT((s.segment<2>(physics::kVx) - f.guess.v0).norm(), 1e-14);
  EXPECT_LT((s.segment<3>(physics::kWx) - f.guess.w0).norm(), 1e-12);
}

TEST(Shot, SimulatesEachLaunchOnceAndARunWithSensitivitiesServesOneWithout) {
  const HeldShot f = FollowShot();
  Shot shot(f.q, f.held, Paper(), f.options);
  const physics::Arrival& plain = shot.Arrive(f.held.speed, f.held.heading, false);
  EXPECT_EQ(&shot.Arrive(f.held.speed, f.held.heading, false), &plain);
  EXPECT_EQ(shot.simulations(), 1);
  const physics::Arrival& with = shot.Arrive(f.held.speed, f.held.heading, true);
  EXPECT_EQ(shot.simulations(), 2) << "the first run has no sensitivities";
  ASSERT_TRUE(with.sensitivity);
  EXPECT_EQ(with.state, plain.state) << "the sensitivities do not change the states";
  shot.Arrive(f.held.speed + 0.1, f.held.heading, true);
  shot.Arrive(f.held.speed + 0.1, f.held.heading, false);
  EXPECT_EQ(shot.simulations(), 3);
}

TEST(Shot, TheMissIsTheArrivalLessTheTargetAndItsJacobianTheSensitivities) {
  HeldShot f = FollowShot();
  f.options.simulation.tolerance = 1e-11;  // central differences of runs this close
  Shot shot(f.q, f.held, Paper(), f.options);
  const double s = f.held.speed, theta = f.held.heading, h = 1e-4;
  Eigen::Vector2d miss;
  Eigen::Matrix2d jacobian;
  ASSERT_TRUE(shot.Miss(s, theta, &miss, &jacobian));
  EXPECT_EQ(miss, Eigen::Vector2d(shot.Arrive(s, theta, false).state.head<2>() - f.q.to));
  const double launch[2] = {s, theta};
  EXPECT_EQ(shot.Close(launch), miss.norm() < f.options.miss_tolerance);
  Eigen::Vector2d plus, minus;
  ASSERT_TRUE(shot.Miss(s + h, theta, &plus, nullptr) && shot.Miss(s - h, theta, &minus, nullptr));
  EXPECT_LT((jacobian.col(0) - (plus - minus) / (2 * h)).norm(), 1e-5 * jacobian.col(0).norm());
  ASSERT_TRUE(shot.Miss(s, theta + h, &plus, nullptr) && shot.Miss(s, theta - h, &minus, nullptr));
  EXPECT_LT((jacobian.col(1) - (plus - minus) / (2 * h)).norm(), 1e-5 * jacobian.col(1).norm());
}

}  // namespace
}  // namespace billiard::planner
