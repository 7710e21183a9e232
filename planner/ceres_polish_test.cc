// Levenberg-Marquardt on (speed, heading): from the closed form's launch to the tolerance with
// either Jacobian, within the speed bounds.
#include "planner/ceres_polish.h"

#include <gtest/gtest.h>

#include "planner/testing/held_shot.h"

namespace billiard::planner {
namespace {

using testing::Paper;

// A draw with side spin on the paper's set, refined from its closed-form launch.
class CeresPolishTest : public ::testing::Test {
 protected:
  double MissAt(Shot& shot, const double launch[2]) {
    return (shot.Arrive(launch[0], launch[1], false).state.head<2>() - draw_.q.to).norm();
  }

  testing::HeldShot draw_{{0.5, 0.3}, {1.7, 1.0}, 0.2, SpinStyle::kDraw, 12.0};
};

TEST_F(CeresPolishTest, ReachesTheToleranceWithEitherJacobian) {
  for (const JacobianMethod method :
       {JacobianMethod::kSensitivities, JacobianMethod::kCentralDifferences}) {
    PlannerOptions options;
    options.jacobian = method;
    Shot shot(draw_.q, draw_.held, Paper(), options);
    double launch[2] = {draw_.held.speed, draw_.held.heading};
    EXPECT_GT(MissAt(shot, launch), 1e-3) << "the closed form's centimetres";
    const int iterations = Polish(shot, launch, options.max_iterations);
    EXPECT_GE(iterations, 1);
    EXPECT_LT(MissAt(shot, launch), options.miss_tolerance);
  }
}

TEST_F(CeresPolishTest, WithoutIterationsSimulatesNothing) {
  const PlannerOptions options;
  Shot shot(draw_.q, draw_.held, Paper(), options);
  double launch[2] = {draw_.held.speed, draw_.held.heading};
  EXPECT_EQ(Polish(shot, launch, 0), 0);
  EXPECT_EQ(shot.simulations(), 0);
  EXPECT_EQ(launch[0], draw_.held.speed);
}

TEST_F(CeresPolishTest, KeepsTheSpeedWithinItsBounds) {
  const PlannerOptions options;
  const double cap = 0.9 * draw_.held.speed;  // slower than any launch that reaches the target
  HeldSpin capped = draw_.held;
  capped.speeds.max = cap;
  Shot shot(draw_.q, capped, Paper(), options);
  double launch[2] = {draw_.held.speed, draw_.held.heading};
  Polish(shot, launch, options.max_iterations);
  EXPECT_LE(launch[0], cap);
  EXPECT_GT(MissAt(shot, launch), 1e-2) << "short of the target";
}

}  // namespace
}  // namespace billiard::planner
