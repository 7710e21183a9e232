// The closed-form model against the formulas of Jaroukh 2019 (with its misprints corrected).
#include "sim/physics/closed_form.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

ClosedFormParameters Paper() { return ClosedFormParameters::From(testing::PaperParameters()); }

TEST(ClosedForm, RollingResistanceOfThePaperSetIsThreeHundredths) {
  EXPECT_NEAR(Paper().mu_roll, 0.03, 1e-15);  // a d / (5 r) = 0.003 / 0.1
}

TEST(ClosedForm, SlideTimeVelocityAndDistanceFollowEquationsEightToTen) {
  const ClosedFormParameters p = Paper();
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> v(-2.0, 2.0), w(-150.0, 150.0);
  for (int i = 0; i < 100; ++i) {
    const BallState s0 = MakeBallState(0.3, 0.4, v(rng), v(rng), w(rng), w(rng), w(rng));
    const ClosedFormTrajectory traj(p, s0);
    const Eigen::Vector2d v0 = s0.segment<2>(kVx);
    const Eigen::Vector2d z_cross_w(-s0[kWy], s0[kWx]);
    const Eigen::Vector2d u0 = v0 + p.radius * z_cross_w;
    const double t1 = 2.0 * u0.norm() / (7.0 * p.mu_slide * p.gravity);            // eq. 8
    const Eigen::Vector2d v1 = 5.0 / 7.0 * v0 - 2.0 / 7.0 * p.radius * z_cross_w;  // eq. 9
    const Eigen::Vector2d dx1 = 2.0 * u0.norm() / (49.0 * p.mu_slide * p.gravity) *
                                (6.0 * v0 - p.radius * z_cross_w);  // eq. 10
    EXPECT_NEAR(traj.slide_end_time(), t1, 1e-14);
    const BallState s1 = traj.slide_end_state();
    EXPECT_NEAR((s1.segment<2>(kVx) - v1).norm(), 0.0, 1e-12);
    EXPECT_NEAR((s1.segment<2>(kX) - s0.segment<2>(kX) - dx1).norm(), 0.0, 1e-12);
    // At the end of sliding the contact point is at rest.
    EXPECT_NEAR(s1[kVx] - p.radius * s1[kWy], 0.0, 1e-12);
    EXPECT_NEAR(s1[kVy] + p.radius * s1[kWx], 0.0, 1e-12);
    EXPECT_EQ(s1[kWz], s0[kWz]);
  }
}

TEST(ClosedForm, OneDimensionalShotMatchesTheInverseFormulas) {
  // Eqs. 17-23: with Z = v0 - R w0 and N = 5 v0 + 2 R w0 the slide ends at
  // x1 - x0 = 2/49 Z (N + Z) / (mu_s g) with v1 = N / 7, and the ball rolls
  // x2 - x1 = 7/10 v1^2 / (mu_r g) further.
  const ClosedFormParameters p = Paper();
  const double v0 = 1.5, w0 = 20.0;  // forward roll w0 > 0 in the paper's 1D convention
  const double z = v0 - p.radius * w0, n = 5 * v0 + 2 * p.radius * w0;
  // In table coordinates a forward roll along +y is wx = -w0.
  const ClosedFormTrajectory traj(p, MakeBallState(0, 0, 0, v0, -w0, 0, 0));
  const double x1 = 2.0 / 49.0 * z * (n + z) / (p.mu_slide * p.gravity);
  const double v1 = n / 7.0;
  const double x2 = x1 + 0.7 * v1 * v1 / (p.mu_roll * p.gravity);
  EXPECT_NEAR(traj.slide_end_state()[kY], x1, 1e-12);
  EXPECT_NEAR(traj.slide_end_state()[kVy], v1, 1e-12);
  EXPECT_NEAR(traj.At(1e3)[kY], x2, 1e-12);
  EXPECT_NEAR(traj.stop_time(), traj.slide_end_time() + 7.0 * v1 / (5.0 * p.mu_roll * p.gravity),
              1e-12);  // eq. 15 as corrected
}

TEST(ClosedForm, RollingBallOfFigureSixStopsAfterTheNotesDistance) {
  const ClosedFormTrajectory traj(Paper(), testing::PaperFigureStates()[0]);
  EXPECT_EQ(traj.slide_end_time(), 0.0);
  EXPECT_NEAR(traj.At(100.0)[kY], 2.3785, 1e-4);
  EXPECT_EQ(traj.At(100.0)[kVy], 0.0);
}

TEST(ClosedForm, StateIsContinuousAcrossThePhaseChanges) {
  const ClosedFormTrajectory traj(Paper(), MakeBallState(0, 0, 0.3, 1.2, 60, -20, 5));
  for (double t : {traj.slide_end_time(), traj.stop_time()}) {
    const BallState before = traj.At(t - 1e-9), after = traj.At(t + 1e-9);
    EXPECT_LT((before.head<4>() - after.head<4>()).norm(), 1e-7) << t;
  }
}

TEST(ClosedForm, KineticEnergyNeverIncreases) {
  const ModelParameters params = testing::PaperParameters();
  for (const BallState& s0 : testing::PaperFigureStates()) {
    testing::ExpectEnergyNeverRises(ClosedFormTrajectory(Paper(), s0), params, 8.0, 8000, 0.0,
                                    1e-12);
  }
}

TEST(ClosedForm, BallWithoutSlipOrSpeedStaysPut) {
  const ClosedFormTrajectory traj(Paper(), MakeBallState(1, 2, 0, 0, 0, 0, 3));
  EXPECT_EQ(traj.stop_time(), 0.0);
  EXPECT_EQ(traj.At(5.0), MakeBallState(1, 2, 0, 0, 0, 0, 3));
}

}  // namespace
}  // namespace billiard::physics
