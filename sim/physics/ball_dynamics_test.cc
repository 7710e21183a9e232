// The 5-DOF equations of motion: their Jacobian, their invariants, and their limit.
#include "sim/physics/ball_dynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

TEST(BallDynamics, JacobianMatchesCentralDifferences) {
  const ModelParameters p = testing::PaperParameters();
  const BallDynamics<ApproximateFrictionModel> approx(p, {p.contact});
  const BallDynamics<IntegralFrictionModel> integral(p, {IntegralFriction(), p.contact.eps_t});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> v(-1.0, 1.0), w(-100.0, 100.0);
  for (int i = 0; i < 20; ++i) {
    const BallState s = MakeBallState(0.1, 0.2, v(rng), v(rng), w(rng), w(rng), w(rng));
    for (int model = 0; model < 2; ++model) {
      BallState f;
      StateJacobian jac;
      model == 0 ? approx.DerivativeAndJacobian(s, &f, &jac)
                 : integral.DerivativeAndJacobian(s, &f, &jac);
      const auto rhs = [&](const BallState& x) {
        return model == 0 ? approx.Derivative(x) : integral.Derivative(x);
      };
      EXPECT_LT((f - rhs(s)).norm(), 1e-9 * (1 + f.norm()));
      for (int j = 0; j < 7; ++j) {
        const double h = 1e-6 * std::max(1.0, std::abs(s[j]));
        BallState plus = s, minus = s;
        plus[j] += h;
        minus[j] -= h;
        const BallState column = (rhs(plus) - rhs(minus)) / (2 * h);
        EXPECT_LT((jac.col(j) - column).norm(), 1e-5 * (1 + column.norm()))
            << "model " << model << " column " << j;
      }
    }
  }
}

// X, vx, wy, wz -> -X, -vx, -wy, -wz maps trajectories onto their mirror images.
BallState Mirror(BallState s) {
  for (int i : {kX, kVx, kWy, kWz}) s[i] = -s[i];
  return s;
}

TEST(BallDynamics, MirroredStartGivesTheMirroredTrajectory) {
  const ModelParameters p = testing::PaperParameters();
  for (const BallState& s0 : testing::PaperFigureStates()) {
    const SimulationResult a = Simulate(p, s0, 8.0);
    const SimulationResult b = Simulate(p, Mirror(s0), 8.0);
    for (double t = 0.0; t <= 8.0; t += 0.25) {
      EXPECT_LT((Mirror(a.trajectory->At(t)) - b.trajectory->At(t)).norm(), 1e-12) << t;
    }
  }
}

TEST(BallDynamics, KineticEnergyNeverIncreasesOnThePaperFigures) {
  const ModelParameters p = testing::PaperParameters();
  for (const BallState& s0 : testing::PaperFigureStates()) {
    // Dense output is third order: allow its interpolation error, nothing more.
    testing::ExpectEnergyNeverRises(*Simulate(p, s0, 8.0).trajectory, p, 8.0, 8000, 1e-9);
  }
}

TEST(BallDynamics, RollingBallOfFigureSixStopsAfterTheNotesDistance) {
  const SimulationResult r =
      Simulate(testing::PaperParameters(), testing::PaperFigureStates()[0], 8.0);
  EXPECT_NEAR(r.final_state[kY], 2.3785, 1e-4);
  EXPECT_EQ(r.final_state[kX], 0.0);
}

TEST(BallDynamics, ConvergesToTheClosedFormAsRegularizationVanishes) {
  // wz = 0 and d = 0: no pivot friction and no rolling resistance, so the only difference from
  // the Coulomb point-contact model of Jaroukh 2019 is the regularization eps_t.
  ModelParameters p = testing::PaperParameters();
  p.contact.d = 0.0;
  const BallState s0 = MakeBallState(0, 0, 0.4, 1.0, 30.0, -10.0, 0.0);
  const ClosedFormTrajectory exact(ClosedFormParameters::From(p), s0);
  const double t_end = 1.0;  // well past the end of sliding (0.16 s)
  double previous = 1.0;
  for (double eps : {1e-1, 1e-2, 1e-3, 1e-4}) {
    p.contact.eps_t = p.contact.eps_r = eps;
    SimulationOptions options;
    options.tolerance = 1e-10;
    const BallState s = Simulate(p, s0, t_end, options).final_state;
    const double error = (s.head<4>() - exact.At(t_end).head<4>()).norm();
    EXPECT_LT(error, 0.5 * previous) << "eps = " << eps;
    previous = error;
  }
  EXPECT_LT(previous, 1e-5);
}

}  // namespace
}  // namespace billiard::physics
