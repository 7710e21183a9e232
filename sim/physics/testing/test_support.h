// Shared fixtures of the physics tests: the paper's parameters and initial states, and linear
// problems with known solutions for the integrators. A testing library (physics_testing): it may
// include the physics, the parameter sets (sim/params/) and GoogleTest; no production code
// includes it.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <array>
#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/physics/ball_dynamics.h"
#include "sim/physics/ball_state.h"
#include "sim/physics/dense_trajectory.h"
#include "sim/physics/integrator.h"
#include "sim/physics/parameters.h"
#include "sim/physics/trajectory.h"

namespace billiard::physics::testing {

inline ModelParameters PaperParameters() { return params::LoadParameters("paper"); }

// X = Y = 0, vx = 0, vy = 1 m/s and the spins of Figs. 6-10 of Kudra et al. 2016.
inline std::array<BallState, 5> PaperFigureStates() {
  return {MakeBallState(0, 0, 0, 1, -50, 0, 0), MakeBallState(0, 0, 0, 1, -50, 5, 0),
          MakeBallState(0, 0, 0, 1, 150, 5, 0), MakeBallState(0, 0, 0, 1, -50, -3.5, -150),
          MakeBallState(0, 0, 0, 1, 150, 0, -150)};
}

// Samples the trajectory at `samples` equal intervals of (0, t_end] and expects every state to be
// finite and the kinetic energy never to rise by more than previous * rel_slack + abs_slack.
inline void ExpectEnergyNeverRises(const Trajectory& trajectory, const ModelParameters& p,
                                   double t_end, int samples, double abs_slack,
                                   double rel_slack = 0.0) {
  double previous = KineticEnergy(trajectory.At(0.0), p.ball.mass, p.ball.radius);
  for (int i = 1; i <= samples; ++i) {
    const double t = t_end * i / samples;
    const BallState s = trajectory.At(t);
    ASSERT_TRUE(s.allFinite()) << "t = " << t;
    const double e = KineticEnergy(s, p.ball.mass, p.ball.radius);
    EXPECT_LE(e, previous * (1 + rel_slack) + abs_slack) << "t = " << t;
    previous = e;
  }
}

// x' = A x with A = V diag(lambda) V^-1 and a fixed, well-conditioned V: a problem with known
// solution V exp(lambda t) V^-1 x0 for testing the integrators.
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

inline IntegratorOptions UniformTolerance(double tol) {
  IntegratorOptions options;
  options.abs_tol = BallState::Constant(tol);
  return options;
}

inline LinearProblem MakeLinearProblem(const BallState& lambda) {
  LinearProblem p;
  p.lambda = lambda;
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

// The global error at t = 2 s falls as the tolerance is tightened, and stays within 100 tol.
template <template <class> class StepperT>
void ExpectGlobalErrorFallsWithTheTolerance(const LinearProblem& p) {
  const BallState x0 = BallState::Constant(1.0);
  double previous = 1.0;
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const IntegrationResult r =
        IntegrateWith<StepperT>(p.system, x0, 0.0, 2.0, UniformTolerance(tol), nullptr);
    const double error = (r.state - p.Exact(x0, 2.0)).norm();
    EXPECT_LT(error, previous) << tol;
    EXPECT_LT(error, 100 * tol) << tol;
    previous = error;
  }
}

// The dense output at tolerance 1e-9 is within 1e-6 of the exact solution between the steps.
template <template <class> class StepperT>
void ExpectDenseOutputInterpolatesBetweenSteps(const LinearProblem& p) {
  const BallState x0 = BallState::Constant(1.0);
  DenseTrajectory dense;
  IntegrateWith<StepperT>(p.system, x0, 0.0, 3.0, UniformTolerance(1e-9), nullptr, &dense);
  for (double t = 0.013; t < 3.0; t += 0.0517) {
    EXPECT_LT((dense.At(t) - p.Exact(x0, t)).norm(), 1e-6) << t;
  }
}

}  // namespace billiard::physics::testing
