// Levenberg-Marquardt on (speed, heading): from the closed form's launch to the tolerance with
// either Jacobian, within the speed bounds.
#include "planner/ceres_polish.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"

namespace billiard::planner {
namespace {

// A draw with side spin on the paper's set, refined from its closed-form launch.
class CeresPolishTest : public ::testing::Test {
 protected:
  CeresPolishTest() {
    q_.from = {0.5, 0.3};
    q_.to = {1.7, 1.0};
    q_.final_speed = 0.2;
    q_.style = SpinStyle::kDraw;
    q_.side_spin = 12.0;
    held_ = HoldTheSpin(q_, InvertClosedForm(q_, physics::ClosedFormParameters::From(params_)),
                        params_);
  }

  double MissAt(Shot& shot, const double launch[2]) {
    return (shot.Arrive(launch[0], launch[1], false).state.head<2>() - q_.to).norm();
  }

  const physics::ModelParameters params_ = params::LoadParameters("paper");
  ShotRequest q_;
  HeldSpin held_;
};

TEST_F(CeresPolishTest, ReachesTheToleranceWithEitherJacobian) {
  for (const JacobianMethod method :
       {JacobianMethod::kSensitivities, JacobianMethod::kCentralDifferences}) {
    PlannerOptions options;
    options.jacobian = method;
    Shot shot(q_, held_, params_, options);
    double launch[2] = {held_.speed, held_.heading};
    EXPECT_GT(MissAt(shot, launch), 1e-3) << "the closed form's centimetres";
    const int iterations = Polish(shot, launch, options.max_iterations);
    EXPECT_GE(iterations, 1);
    EXPECT_LT(MissAt(shot, launch), options.miss_tolerance);
  }
}

TEST_F(CeresPolishTest, WithoutIterationsSimulatesNothing) {
  const PlannerOptions options;
  Shot shot(q_, held_, params_, options);
  double launch[2] = {held_.speed, held_.heading};
  EXPECT_EQ(Polish(shot, launch, 0), 0);
  EXPECT_EQ(shot.simulations(), 0);
  EXPECT_EQ(launch[0], held_.speed);
}

TEST_F(CeresPolishTest, KeepsTheSpeedWithinItsBounds) {
  const PlannerOptions options;
  const double cap = 0.9 * held_.speed;  // slower than any launch that reaches the target
  HeldSpin capped = held_;
  capped.speeds.max = cap;
  Shot shot(q_, capped, params_, options);
  double launch[2] = {held_.speed, held_.heading};
  Polish(shot, launch, options.max_iterations);
  EXPECT_LE(launch[0], cap);
  EXPECT_GT(MissAt(shot, launch), 1e-2) << "short of the target";
}

}  // namespace
}  // namespace billiard::planner
