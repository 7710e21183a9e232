// RODAS4 on problems with known solutions: accuracy, order, dense output, stiff stability.
#include "rodas4.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ball_dynamics.h"
#include "simulator.h"
#include "test_support.h"

namespace billiard {
namespace {

// Eigenvalues from -0.5 to -1e6 1/s: the spread of the ball's slip and rolling modes.
testing::LinearProblem StiffProblem() {
  BallState lambda;
  lambda << -0.5, -1.0, -3.0, -40.0, -2e3, -1e5, -1e6;
  return testing::MakeLinearProblem(lambda);
}

TEST(Rodas4, StiffLinearProblemIsAccurateAndTakesFewSteps) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  IntegrationStats stats;
  const IntegrationResult r = IntegrateRodas4(p.system, x0, 0.0, 5.0, testing::UniformTolerance(1e-9), &stats);
  EXPECT_EQ(r.t, 5.0);
  EXPECT_LT((r.state - p.Exact(x0, 5.0)).norm(), 1e-7);
  // An explicit method would need ~ 5 s * 1e6 / 3 steps for stability alone.
  EXPECT_LT(stats.steps, 2000);
}

TEST(Rodas4, GlobalErrorFallsWithTheTolerance) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  double previous = 1.0;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const IntegrationResult r = IntegrateRodas4(p.system, x0, 0.0, 2.0, testing::UniformTolerance(tol), nullptr);
    const double error = (r.state - p.Exact(x0, 2.0)).norm();
    EXPECT_LT(error, previous);
    EXPECT_LT(error, 100 * tol);
    previous = error;
  }
}

TEST(Rodas4, DenseOutputInterpolatesBetweenSteps) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  DenseTrajectory dense;
  IntegrateRodas4(p.system, x0, 0.0, 3.0, testing::UniformTolerance(1e-9), nullptr, &dense);
  for (double t = 0.013; t < 3.0; t += 0.0517) {
    EXPECT_LT((dense.At(t) - p.Exact(x0, t)).norm(), 1e-6) << t;
  }
}

TEST(Rodas4, StopPredicateEndsTheIntegrationAtTheFirstStepThatMeetsIt) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  IntegratorOptions options;
  const auto below = [](const BallState& x) { return x.norm() < 0.5; };
  const IntegrationResult r = IntegrateRodas4(p.system, x0, 0.0, 100.0, options, nullptr, nullptr, below);
  EXPECT_TRUE(r.stopped);
  EXPECT_LT(r.state.norm(), 0.5);
  EXPECT_LT(r.t, 100.0);
}

TEST(Rodas4, BallThroughTheEndOfSlidingNeedsHundredsOfStepsNotHundredsOfThousands) {
  // The notes measure ~540,000 explicit Dormand-Prince steps on Fig. 6 over 8 s.
  const SimulationResult r =
      Simulate(testing::PaperParameters(), testing::PaperFigureStates()[0], 8.0);
  EXPECT_LT(r.stats.steps + r.stats.rejected_steps, 1000);
}

}  // namespace
}  // namespace billiard
