// RODAS4 on problems with known solutions: accuracy, order, dense output, stiff stability.
#include "sim/physics/rodas4.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/physics/ball_dynamics.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
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
  const IntegrationResult r =
      IntegrateWith<Rodas4Stepper>(p.system, x0, 0.0, 5.0, testing::UniformTolerance(1e-9), &stats);
  EXPECT_EQ(r.t, 5.0);
  EXPECT_LT((r.state - p.Exact(x0, 5.0)).norm(), 1e-7);
  // An explicit method would need ~ 5 s * 1e6 / 3 steps for stability alone.
  EXPECT_LT(stats.steps, 2000);
}

TEST(Rodas4, GlobalErrorFallsWithTheTolerance) {
  testing::ExpectGlobalErrorFallsWithTheTolerance<Rodas4Stepper>(StiffProblem());
}

TEST(Rodas4, DenseOutputInterpolatesBetweenSteps) {
  testing::ExpectDenseOutputInterpolatesBetweenSteps<Rodas4Stepper>(StiffProblem());
}

TEST(Rodas4, StopPredicateEndsTheIntegrationAtTheFirstStepThatMeetsIt) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  IntegratorOptions options;
  const auto below = [](const BallState& x) { return x.norm() < 0.5; };
  const IntegrationResult r =
      IntegrateWith<Rodas4Stepper>(p.system, x0, 0.0, 100.0, options, nullptr, nullptr, below);
  EXPECT_TRUE(r.stopped);
  EXPECT_LT(r.state.norm(), 0.5);
  EXPECT_LT(r.t, 100.0);
}

// The predicate holds only at the end state, reached by the step clipped to t_end: it is asked
// there too. (It was not: a planner's ball whose speed fell to the arrival speed inside a rolling
// step of seconds that ended at its time limit was reported as never arriving, 4.25 m from where
// it started instead of 3.63 m.)
TEST(Rodas4, StopPredicateIsAskedAfterTheStepThatReachesTheEnd) {
  const testing::LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  const IntegratorOptions options = testing::UniformTolerance(1e-6);
  const IntegrationResult free_run =
      IntegrateWith<Rodas4Stepper>(p.system, x0, 0.0, 5.0, options, nullptr);
  const double end_norm = free_run.state.norm();
  const auto at_end = [end_norm](const BallState& x) { return x.norm() <= end_norm; };
  const IntegrationResult r =
      IntegrateWith<Rodas4Stepper>(p.system, x0, 0.0, 5.0, options, nullptr, nullptr, at_end);
  EXPECT_TRUE(r.stopped);
  EXPECT_EQ(r.t, 5.0);
  EXPECT_EQ(r.state, free_run.state);
}

TEST(Rodas4, BallThroughTheEndOfSlidingNeedsHundredsOfStepsNotHundredsOfThousands) {
  // The notes measure ~540,000 explicit Dormand-Prince steps on Fig. 6 over 8 s.
  const SimulationResult r =
      Simulate(testing::PaperParameters(), testing::PaperFigureStates()[0], 8.0);
  EXPECT_LT(r.stats.steps + r.stats.rejected_steps, 1000);
}

}  // namespace
}  // namespace billiard::physics
