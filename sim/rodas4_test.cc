// RODAS4 on problems with known solutions: accuracy, order, dense output, stiff stability.
#include "rodas4.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "ball_dynamics.h"
#include "simulator.h"
#include "test_support.h"

namespace billiard {
namespace {

// x' = A x with A = V diag(lambda) V^-1: exact solution V exp(lambda t) V^-1 x0.
struct LinearSystem {
  StateJacobian a;
  BallState Derivative(const BallState& x) const { return a * x; }
  void DerivativeAndJacobian(const BallState& x, BallState* f, StateJacobian* jac) const {
    *f = a * x;
    *jac = a;
  }
};

struct LinearProblem {
  LinearSystem system;
  StateJacobian v, v_inv;
  BallState lambda;
  BallState Exact(const BallState& x0, double t) const {
    return v * (lambda * t).array().exp().matrix().asDiagonal() * (v_inv * x0);
  }
};

// Eigenvalues from -0.5 to -1e6 1/s: the spread of the ball's slip and rolling modes.
LinearProblem StiffProblem() {
  LinearProblem p;
  p.lambda << -0.5, -1.0, -3.0, -40.0, -2e3, -1e5, -1e6;
  p.v = StateJacobian::Identity();
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) {
      if (i != j) p.v(i, j) = 0.1 * std::sin(1.0 + i + 2.0 * j);
    }
  }
  p.v_inv = p.v.inverse();
  p.system.a = p.v * p.lambda.asDiagonal() * p.v_inv;
  return p;
}

Rodas4Options Tolerance(double tol) {
  Rodas4Options options;
  options.abs_tol = BallState::Constant(tol);
  return options;
}

TEST(Rodas4, StiffLinearProblemIsAccurateAndTakesFewSteps) {
  const LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  IntegrationStats stats;
  const Rodas4Result r = IntegrateRodas4(p.system, x0, 0.0, 5.0, Tolerance(1e-9), &stats);
  EXPECT_EQ(r.t, 5.0);
  EXPECT_LT((r.state - p.Exact(x0, 5.0)).norm(), 1e-7);
  // An explicit method would need ~ 5 s * 1e6 / 3 steps for stability alone.
  EXPECT_LT(stats.steps, 2000);
}

TEST(Rodas4, GlobalErrorFallsWithTheTolerance) {
  const LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  double previous = 1.0;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const Rodas4Result r = IntegrateRodas4(p.system, x0, 0.0, 2.0, Tolerance(tol), nullptr);
    const double error = (r.state - p.Exact(x0, 2.0)).norm();
    EXPECT_LT(error, previous);
    EXPECT_LT(error, 100 * tol);
    previous = error;
  }
}

TEST(Rodas4, DenseOutputInterpolatesBetweenSteps) {
  const LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  DenseTrajectory dense;
  IntegrateRodas4(p.system, x0, 0.0, 3.0, Tolerance(1e-9), nullptr, &dense);
  for (double t = 0.013; t < 3.0; t += 0.0517) {
    EXPECT_LT((dense.At(t) - p.Exact(x0, t)).norm(), 1e-6) << t;
  }
}

TEST(Rodas4, StopPredicateEndsTheIntegrationAtTheFirstStepThatMeetsIt) {
  const LinearProblem p = StiffProblem();
  const BallState x0 = BallState::Constant(1.0);
  Rodas4Options options;
  const auto below = [](const BallState& x) { return x.norm() < 0.5; };
  const Rodas4Result r = IntegrateRodas4(p.system, x0, 0.0, 100.0, options, nullptr, nullptr, below);
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
