// The hard cases of the 5-DOF model: each must give finite results whose kinetic energy never
// grows and which converge as the tolerance is tightened 100x.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "sim/physics/simulator.h"
#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

struct HardCase {
  std::string name;
  BallState initial;
  double t_end;
  double eps = 0.01;  // eps_t = eps_r
};

std::ostream& operator<<(std::ostream& os, const HardCase& c) { return os << c.name; }

class HardCases : public ::testing::TestWithParam<HardCase> {
 protected:
  ModelParameters Params() const {
    ModelParameters p = testing::PaperParameters();
    p.contact.eps_t = p.contact.eps_r = GetParam().eps;
    return p;
  }
};

TEST_P(HardCases, FiniteEnergyDecreasingAndConvergedUnderTolerance) {
  const HardCase& c = GetParam();
  const ModelParameters p = Params();
  SimulationOptions loose, tight;
  tight.tolerance = loose.tolerance / 100;
  const SimulationResult a = Simulate(p, c.initial, c.t_end, loose);
  const SimulationResult b = Simulate(p, c.initial, c.t_end, tight);
  ASSERT_TRUE(a.final_state.allFinite());
  ASSERT_TRUE(b.final_state.allFinite());
  EXPECT_LT((a.final_state.head<2>() - b.final_state.head<2>()).norm(), 1e-6);
  EXPECT_LT((a.final_state.tail<5>() - b.final_state.tail<5>()).norm(), 1e-4);

  testing::ExpectEnergyNeverRises(*b.trajectory, p, c.t_end, 4000, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(
    PhysicsCore, HardCases,
    ::testing::Values(
        HardCase{"TinyRegularization", MakeBallState(0, 0, 0, 1, 150, 5, 0), 8.0, 1e-6},
        HardCase{"TinyRegularizationWithSpin", MakeBallState(0, 0, 0, 1, -50, -3.5, -150), 8.0,
                 1e-6},
        HardCase{"SideSpinPlus1000", MakeBallState(0, 0, 0, 1, -50, 0, 1000), 8.0},
        HardCase{"SideSpinMinus1000", MakeBallState(0, 0, 0, 1, -50, 0, -1000), 8.0},
        HardCase{"AtRestWithOnlySideSpin", MakeBallState(0.3, 0.2, 0, 0, 0, 0, 80), 8.0},
        HardCase{"PureBackspinReversal", MakeBallState(0, 0, 0, 1, 150, 0, 0), 8.0},
        HardCase{"SixtySecondHorizon", MakeBallState(0, 0, 0, 1, -50, -3.5, -150), 60.0},
        HardCase{"ZeroVelocityWithTopspin", MakeBallState(0, 0, 0, 0, -60, 20, 0), 8.0},
        HardCase{"ZeroVelocityWithSpinAndSideSpin", MakeBallState(0, 0, 0, 0, 40, 0, -300), 8.0}),
    [](const ::testing::TestParamInfo<HardCase>& info) { return info.param.name; });

TEST(HardCaseBehaviour, BallAtRestWithOnlySideSpinStaysPutAndStopsSpinning) {
  const ModelParameters p = testing::PaperParameters();
  const BallState s0 = MakeBallState(0.3, 0.2, 0, 0, 0, 0, 80);
  const SimulationResult r = Simulate(p, s0, 8.0);
  EXPECT_EQ(r.final_state.head<6>(), s0.head<6>());
  EXPECT_LT(std::abs(r.final_state[kWz]), 1e-3);
  // Pivot deceleration 5/2 g a mu (3 pi/16) / r^2 while |wz| >> eps_t / b_M.
  const double rate = 2.5 * p.ball.gravity * p.contact.patch_radius * p.contact.mu *
                      (3 * M_PI / 16) / (p.ball.radius * p.ball.radius);
  EXPECT_NEAR(r.trajectory->At(1.0)[kWz], 80 - rate, 0.05);
}

TEST(HardCaseBehaviour, BackspinReversesTheBall) {
  const SimulationResult r =
      Simulate(testing::PaperParameters(), MakeBallState(0, 0, 0, 1, 150, 0, 0), 8.0);
  double furthest = 0.0;
  for (double t = 0; t < 8; t += 0.01) furthest = std::max(furthest, r.trajectory->At(t)[kY]);
  EXPECT_GT(furthest, 0.1);
  EXPECT_LT(r.final_state[kY], furthest - 0.05);  // it came back
  EXPECT_EQ(r.final_state[kX], 0.0);
}

TEST(HardCaseBehaviour, ZeroStateStaysExactlyZero) {
  const SimulationResult r = Simulate(testing::PaperParameters(), BallState::Zero(), 8.0);
  EXPECT_EQ(r.final_state, BallState::Zero());
}

TEST(HardCaseBehaviour, SideSpinCurvesThePathOppositeWays) {
  const ModelParameters p = testing::PaperParameters();
  const double x_plus = Simulate(p, MakeBallState(0, 0, 0, 1, -50, 0, 1000), 8.0).final_state[kX];
  const double x_minus = Simulate(p, MakeBallState(0, 0, 0, 1, -50, 0, -1000), 8.0).final_state[kX];
  EXPECT_GT(std::abs(x_plus), 1e-3);
  EXPECT_EQ(x_plus, -x_minus);
}

TEST(SimulatorInput, RejectsNonFiniteStatesAndNegativeTimes) {
  const ModelParameters p = testing::PaperParameters();
  BallState s = testing::PaperFigureStates()[0];
  EXPECT_THROW(Simulate(p, s, -1.0), std::invalid_argument);
  EXPECT_THROW(Simulate(p, s, NAN), std::invalid_argument);
  s[kWz] = NAN;
  EXPECT_THROW(Simulate(p, s, 1.0), std::invalid_argument);
}

TEST(SimulatorModels, AllModelsAgreeOnARollingBallWithoutSpin) {
  // Rolling from the start with wz = 0: the integral and approximate models coincide (eq. 11),
  // and the closed form is the eps -> 0 limit.
  const ModelParameters p = testing::PaperParameters();
  const BallState s0 = testing::PaperFigureStates()[0];
  SimulationOptions integral;
  integral.model = Model::kIntegral;
  SimulationOptions closed;
  closed.model = Model::kClosedForm;
  const double approx_y = Simulate(p, s0, 8.0).final_state[kY];
  EXPECT_NEAR(Simulate(p, s0, 8.0, integral).final_state[kY], approx_y, 1e-6);
  EXPECT_NEAR(Simulate(p, s0, 8.0, closed).final_state[kY], approx_y, 1e-4);
}

TEST(SimulatorModels, EveryModelRunsThePaperFiguresToEightSeconds) {
  const ModelParameters p = testing::PaperParameters();
  for (Model m : {Model::kApproximate, Model::kIntegral, Model::kClosedForm}) {
    SimulationOptions options;
    options.model = m;
    for (const BallState& s0 : testing::PaperFigureStates()) {
      const SimulationResult r = Simulate(p, s0, 8.0, options);
      EXPECT_TRUE(r.final_state.allFinite()) << ModelName(m);
      EXPECT_LT(r.final_state.segment<2>(kVx).norm(), 1e-3) << ModelName(m);
    }
  }
}

}  // namespace
}  // namespace billiard::physics
