// Forward sensitivities against exact solutions and central differences, and the arrival events
// against the simulator.
#include "sim/physics/sensitivity.h"

#include <gtest/gtest.h>

#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

TEST(Sensitivity, StiffLinearProblemGivesTheMatrixExponential) {
  // x' = A x: S(t) = V exp(lambda t) V^-1, with modes from -0.5 to -1e6 1/s as in the ball.
  BallState lambda;
  lambda << -0.5, -1.0, -3.0, -40.0, -2e3, -1e5, -1e6;
  const testing::LinearProblem p = testing::MakeLinearProblem(lambda);
  Rodas4SensitivityStepper<testing::LinearSystem> stepper(p.system);
  const IntegrationResult r = IntegrateAdaptive(stepper, BallState::Constant(1.0), 0.0, 2.0,
                                                testing::UniformTolerance(1e-9), nullptr);
  Sensitivity exact;
  for (int j = 0; j < 7; ++j) exact.col(j) = p.Exact(BallState::Unit(j), r.t);
  EXPECT_LT((stepper.sensitivity() - exact).norm(), 1e-6 * exact.norm());
}

// d (X, Y) at arrival / d initial state, by central differences at a tight tolerance.
Eigen::Matrix<double, 2, 7> ArrivalDifferences(const ModelParameters& p, const BallState& x0,
                                               double speed) {
  SimulationOptions tight;
  tight.tolerance = 1e-11;
  Eigen::Matrix<double, 2, 7> d;
  for (int j = 0; j < 7; ++j) {
    const double h = j < 4 ? 1e-5 : 1e-3;  // metres and m/s, or rad/s
    BallState plus = x0, minus = x0;
    plus[j] += h;
    minus[j] -= h;
    d.col(j) = (SimulateArrival(p, plus, speed, 60.0, tight).state.head<2>() -
                SimulateArrival(p, minus, speed, 60.0, tight).state.head<2>()) /
               (2 * h);
  }
  return d;
}

TEST(Sensitivity, ArrivalSensitivitiesAgreeWithCentralDifferences) {
  const ModelParameters p = testing::PaperParameters();
  // Rolling, stun with side spin, draw with side spin, and the paper's spin-heavy figures.
  const BallState launches[] = {MakeBallState(0.5, 0.3, 1.2, 0.8, -40, 60, 0),
                                MakeBallState(0.2, 0.2, 1.5, 0.3, 0, 0, 25),
                                MakeBallState(0.5, 0.3, 1.445, 0.8436, 42.18, -72.25, 12),
                                testing::PaperFigureStates()[3], testing::PaperFigureStates()[4]};
  for (const BallState& x0 : launches) {
    for (double speed : {0.0, 0.2}) {
      SimulationOptions planner;
      planner.tolerance = 1e-6;
      const Arrival a = SimulateArrival(p, x0, speed, 60.0, planner, true);
      ASSERT_TRUE(a.reached);
      const Eigen::Matrix<double, 2, 7> fd = ArrivalDifferences(p, x0, speed);
      const Eigen::Matrix<double, 2, 7> s = a.sensitivity->topRows<2>();
      for (int j = 0; j < 7; ++j) {
        EXPECT_LT((s.col(j) - fd.col(j)).norm(), 5e-3 * std::max(fd.col(j).norm(), 1e-3))
            << "launch " << x0.transpose() << ", speed " << speed << ", column " << j << "\n"
            << s << "\n"
            << fd;
      }
    }
  }
}

TEST(Sensitivity, ArrivalAtRestIsWhereTheSimulationEnds) {
  const ModelParameters p = testing::PaperParameters();
  for (const BallState& x0 : testing::PaperFigureStates()) {
    const Arrival a = SimulateArrival(p, x0, 0.0, 60.0);
    ASSERT_TRUE(a.reached);
    const SimulationResult r = Simulate(p, x0, 60.0);
    EXPECT_EQ(a.time, r.rest_time);
    EXPECT_EQ(a.state.head<2>(), r.final_state.head<2>());
  }
}

TEST(Sensitivity, ArrivalAtSpeedIsTheFirstTimeTheSpeedFallsThere) {
  const ModelParameters p = testing::PaperParameters();
  const BallState x0 = MakeBallState(0.0, 0.0, 2.0, 0.5, 0, 0, 30);
  const Arrival a = SimulateArrival(p, x0, 0.7, 60.0);
  ASSERT_TRUE(a.reached);
  EXPECT_NEAR(a.state.segment<2>(kVx).norm(), 0.7, 1e-9);
  for (int i = 0; i < 50; ++i) {  // by index: a sum of 50 increments can land on a.time itself
    const double t = a.time * i / 50;
    EXPECT_GT(a.trajectory->At(t).segment<2>(kVx).norm(), 0.7) << t;
  }
  const Arrival never = SimulateArrival(p, x0, 0.7, 0.1);
  EXPECT_FALSE(never.reached);
  EXPECT_EQ(never.time, 0.1);
}

TEST(Sensitivity, ClosedFormArrivalMatchesItsTrajectory) {
  const ModelParameters p = testing::PaperParameters();
  SimulationOptions closed_form;
  closed_form.model = Model::kClosedForm;
  for (const BallState& x0 : testing::PaperFigureStates()) {
    for (double speed : {0.0, 0.3, 0.9}) {
      const Arrival a = SimulateArrival(p, x0, speed, 60.0, closed_form);
      ASSERT_TRUE(a.reached);
      EXPECT_NEAR(a.state.segment<2>(kVx).norm(), speed, 1e-12);
      EXPECT_GT(a.trajectory->At(a.time * (1 - 1e-6)).segment<2>(kVx).norm(), speed);
    }
  }
  EXPECT_THROW(SimulateArrival(p, testing::PaperFigureStates()[0], 0.0, 60.0, closed_form, true),
               std::invalid_argument);
}

}  // namespace
}  // namespace billiard::physics
