// DOPRI5 on problems with known solutions, and on the ball: same answers as RODAS4, and the cost of
// the stiffness measured.
#include "sim/physics/dopri5.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

// Eigenvalues within two decades: nothing stiff for an explicit method.
testing::LinearProblem MildProblem() {
  BallState lambda;
  lambda << -0.5, -1.0, -2.0, -3.0, -5.0, -10.0, -20.0;
  return testing::MakeLinearProblem(lambda);
}

TEST(Dopri5, GlobalErrorFallsWithTheTolerance) {
  testing::ExpectGlobalErrorFallsWithTheTolerance<Dopri5Stepper>(MildProblem());
}

TEST(Dopri5, DenseOutputInterpolatesBetweenSteps) {
  testing::ExpectDenseOutputInterpolatesBetweenSteps<Dopri5Stepper>(MildProblem());
}

// At 1e-7: DOPRI5's steps sit at its stability limit through the stiff rolling phase, where
// its error estimate is a poor guide, and at the simulator's default (1e-6) its 8 s endpoints are
// 2-13 um from RODAS4's (docs/benchmarks/report.md: dopri5 at 1e-5 is 33 um off).
constexpr double kComparisonTolerance = 1e-7;

SimulationResult SimulateWith(const BallState& s0, Integrator integrator) {
  SimulationOptions options;
  options.integrator = integrator;
  options.tolerance = kComparisonTolerance;
  return Simulate(testing::PaperParameters(), s0, 8.0, options);
}

TEST(Dopri5, AgreesWithRodas4OnThePaperFigures) {
  for (const BallState& s0 : testing::PaperFigureStates()) {
    const SimulationResult a = SimulateWith(s0, Integrator::kDopri5);
    const SimulationResult b = SimulateWith(s0, Integrator::kRodas4);
    EXPECT_LT((a.final_state.head<2>() - b.final_state.head<2>()).norm(), 1e-6) << s0.transpose();
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
}  // namespace billiard::physics
