// The closed-form inverse against the forward closed form (sim/physics/closed_form.h).
#include "planner/closed_form_inverse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/parameters.h"

namespace billiard::planner {
namespace {

physics::ClosedFormParameters Paper() {
  return physics::ClosedFormParameters::From(params::LoadParameters("paper"));
}

// Where the forward model's speed falls to v2 (its rest point when v2 = 0), and the state there.
physics::BallState WhereSpeedFallsTo(const physics::ClosedFormTrajectory& t, double v2) {
  if (v2 == 0.0) return t.At(t.stop_time());
  double lo = t.slide_end_time(), hi = t.stop_time();
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (t.At(mid).segment<2>(physics::kVx).norm() > v2 ? lo : hi) = mid;
  }
  return t.At(lo);
}

TEST(ClosedFormInverse, ForwardModelEndsOnTheTargetForEveryStyleAndSlideLength) {
  const physics::ClosedFormParameters p = Paper();
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int solved = 0;
  for (int i = 0; i < 400; ++i) {
    ShotRequest q;
    q.from = {0.1 + 2.3 * u(rng), 0.1 + 1.0 * u(rng)};
    q.to = {0.1 + 2.3 * u(rng), 0.1 + 1.0 * u(rng)};
    q.final_speed = i % 2 ? 0.0 : 0.5 * u(rng);
    q.side_spin = 20 * (u(rng) - 0.5);
    if (i % 5 == 4) {
      q.slide_length = (q.to - q.from).norm() * u(rng);
    } else {
      q.style = static_cast<SpinStyle>(i % 4);
    }
    const LaunchSolution s = InvertClosedForm(q, p);
    if (!s.ok) {
      // Only a shot still sliding at the target may be refused.
      EXPECT_NE(s.reason.find("sliding"), std::string::npos) << s.reason;
      continue;
    }
    ++solved;
    const physics::BallState start = physics::MakeBallState(q.from.x(), q.from.y(), s.v0.x(),
                                                            s.v0.y(), s.w0.x(), s.w0.y(), s.w0.z());
    const physics::ClosedFormTrajectory forward(p, start);
    const physics::BallState there = WhereSpeedFallsTo(forward, q.final_speed);
    EXPECT_LT((there.head<2>() - q.to).norm(), 1e-9) << "request " << i;
    // Validity of the seed's inverse: v0 >= R w0 >= -5/2 v0 along the shot.
    const Eigen::Vector2d e = (q.to - q.from).normalized();
    const double r_w = p.radius * (e.x() * s.w0.y() - e.y() * s.w0.x());
    EXPECT_GE(s.v0.norm() + 1e-12, r_w);
    EXPECT_GE(r_w, -2.5 * s.v0.norm() - 1e-12);
    EXPECT_NEAR((forward.slide_end_state().head<2>() - q.from).norm(), s.slide_length, 1e-9);
  }
  EXPECT_GT(solved, 300);
}

TEST(ClosedFormInverse, StylesSetTheSpinRatio) {
  const physics::ClosedFormParameters p = Paper();
  ShotRequest q;
  q.to = {1.0, 0.0};
  for (auto [style, ratio] : {std::pair{SpinStyle::kStun, 0.0},
                              {SpinStyle::kNatural, 1.0},
                              {SpinStyle::kFollow, 0.5},
                              {SpinStyle::kDraw, -1.0}}) {
    q.style = style;
    const LaunchSolution s = InvertClosedForm(q, p);
    ASSERT_TRUE(s.ok) << s.reason;
    EXPECT_NEAR(p.radius * s.w0.y() / s.v0.x(), ratio, 1e-12);
  }
  q.style = SpinStyle::kNatural;
  EXPECT_EQ(InvertClosedForm(q, p).slide_length, 0.0);
}

TEST(ClosedFormInverse, RefusesBadRequestsWithAReason) {
  const physics::ClosedFormParameters p = Paper();
  const auto refused = [&](ShotRequest q) {
    const LaunchSolution s = InvertClosedForm(q, p);
    EXPECT_FALSE(s.ok);
    EXPECT_FALSE(s.reason.empty());
  };
  ShotRequest q;
  q.to = {1.0, 0.5};
  ShotRequest nan = q;
  nan.to.x() = NAN;
  refused(nan);
  ShotRequest same = q;
  same.to = same.from;
  refused(same);
  ShotRequest negative = q;
  negative.final_speed = -1;
  refused(negative);
  ShotRequest too_long = q;
  too_long.slide_length = 5.0;
  refused(too_long);
  physics::ClosedFormParameters no_roll = p;
  no_roll.mu_roll = 0.0;
  EXPECT_FALSE(InvertClosedForm(q, no_roll).ok);
}

TEST(ClosedFormInverse, WithoutRollingResistanceTheBallArrivesStillSliding) {
  // mu_r = 0: the speed falls only while the ball slides, so the forward model must come down to
  // v2 on the target before its sliding ends; what cannot is refused with the reason.
  physics::ClosedFormParameters p = Paper();
  p.mu_roll = 0.0;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int solved = 0;
  for (int i = 0; i < 400; ++i) {
    ShotRequest q;
    q.from = {0.1 + 2.3 * u(rng), 0.1 + 1.0 * u(rng)};
    q.to = {0.1 + 2.3 * u(rng), 0.1 + 1.0 * u(rng)};
    q.final_speed = 3.0 * u(rng);
    q.style = static_cast<SpinStyle>(i % 4);
    const LaunchSolution s = InvertClosedForm(q, p);
    if (!s.ok) {
      EXPECT_NE(s.reason.find("without rolling resistance"), std::string::npos) << s.reason;
      continue;
    }
    ++solved;
    const physics::ClosedFormTrajectory forward(
        p, physics::MakeBallState(q.from.x(), q.from.y(), s.v0.x(), s.v0.y(), s.w0.x(), s.w0.y(),
                                  s.w0.z()));
    const double t = forward.TimeAtSpeed(q.final_speed);
    EXPECT_LT(t, forward.slide_end_time()) << "request " << i;
    EXPECT_LT((forward.At(t).head<2>() - q.to).norm(), 1e-9) << "request " << i;
    EXPECT_EQ(s.slide_length, (q.to - q.from).norm());
  }
  EXPECT_GT(solved, 50);

  ShotRequest q;
  q.to = {1.0, 0.5};
  q.final_speed = 0.3;
  q.style = SpinStyle::kNatural;  // rolls at its launch speed for ever
  EXPECT_FALSE(InvertClosedForm(q, p).ok);
  q.slide_length = 0.5;  // reaches v2 where it stops sliding, and rolls on at it
  EXPECT_FALSE(InvertClosedForm(q, p).ok);
  p.mu_slide = 0.0;
  q.slide_length.reset();
  const LaunchSolution frictionless = InvertClosedForm(q, p);
  EXPECT_FALSE(frictionless.ok);
  EXPECT_NE(frictionless.reason.find("never changes"), std::string::npos) << frictionless.reason;
}

}  // namespace
}  // namespace billiard::planner
