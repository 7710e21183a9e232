// DOPRI5 on problems with known solutions, and on the ball: same answers as RODAS4, and the cost of
// the stiffness measured.
#include "dopri5.h"

#include <gtest/gtest.h>

#include <cmath>

#include "simulator.h"
#include "test_support.h"

namespace billiard {
namespace {

// Eigenvalues within two decades: nothing stiff for an explicit method.
testing::LinearProblem MildProblem() {
  BallState lambda;
  lambda << -0.5, -1.0, -2.0, -3.0, -5.0, -10.0, -20.0;
  return testing::MakeLinearProblem(lambda);
}

TEST(Dopri5, GlobalErrorFallsWithTheTolerance) {
  const testing::LinearProblem p = MildProblem();
  const BallState x0 = BallState::Constant(1.0);
  double previous = 1.0;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const IntegrationResult r =
        IntegrateDopri5(p.system, x0, 0.0, 2.0, testing::UniformTolerance(tol), nullptr);
    const double error = (r.state - p.Exact(x0, 2.0)).norm();
    EXPECT_LT(error, previous);
    EXPECT_LT(error, 100 * tol);
    previous = error;
  }
}

TEST(Dopri5, DenseOutputInterpolatesBetweenSteps) {
  const testing::LinearProblem p = MildProblem();
  const BallState x0 = BallState::Constant(1.0);
  DenseTrajectory dense;
  IntegrateDopri5(p.system, x0, 0.0, 3.0, testing::UniformTolerance(1e-9), nullptr, &dense);
  for (double t = 0.013; t < 3.0; t += 0.0517) {
    EXPECT_LT((dense.At(t) - p.Exact(x0, t)).norm(), 1e-6) << t;
  }
}

SimulationResult SimulateWith(const BallState& s0, Integrator integrator) {
  SimulationOptions options;
  options.integrator = integrator;
  return Simulate(testing::PaperParameters(), s0, 8.0, options);
}

TEST(Dopri5, AgreesWithRodas4OnThePaperFigures) {
  for (const BallState& s0 : testing::PaperFigureStates()) {
    const SimulationResult a = SimulateWith(s0, Integrator::kDopri5);
    const SimulationResult b = SimulateWith(s0, Integrator::kRodas4);
    EXPECT_LT((a.final_state.head<2>() - b.final_state.head<2>()).norm(), 1e-6)
        << s0.transpose();
  }
}

// The stiff rolling phase of Fig. 6 holds an explicit step at the stability limit (a few us);
// the notes measured about 540,000 steps without a rest switch.
TEST(Dopri5, PaysForTheStiffnessOfRollingWithThousandsOfTimesTheSteps) {
  const SimulationResult a = SimulateWith(testing::PaperFigureStates()[0], Integrator::kDopri5);
  const SimulationResult b = SimulateWith(testing::PaperFigureStates()[0], Integrator::kRodas4);
  EXPECT_GT(a.stats.steps, 1000 * b.stats.steps);
}

}  // namespace
}  // namespace billiard
