// The plan made of a launch: its prediction read from the launch's one run, and its verdict.
#include "planner/plan_assembly.h"

#include <gtest/gtest.h>

#include <cmath>

#include "planner/testing/held_shot.h"
#include "sim/physics/cue_strike.h"

namespace billiard::planner {
namespace {

using testing::Paper;

class PlanAssemblyTest : public ::testing::Test {
 protected:
  // A stun shot from `from` to `to` on the paper's set, at its closed-form launch.
  void Aim(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double side_spin = 0.0) {
    const testing::HeldShot stun(from, to, 0.0, SpinStyle::kStun, side_spin);
    q_ = stun.q;
    held_ = stun.held;
    launch_[0] = held_.speed;
    launch_[1] = held_.heading;
  }

  const physics::ModelParameters& params_ = Paper();
  PlannerOptions options_;
  ShotRequest q_;
  HeldSpin held_;
  double launch_[2] = {0.0, 0.0};
};

TEST_F(PlanAssemblyTest, ThePredictionIsTheLaunchsRunFromTheBallToWhereItArrives) {
  Aim({0.4, 0.5}, {1.8, 0.9});
  Shot shot(q_, held_, params_, options_);
  ShotPlan plan;
  ASSERT_TRUE(Predict(shot, launch_, &plan));
  EXPECT_EQ(shot.simulations(), 1);
  const physics::BallState start =
      Launch(q_.from, held_.spin_ratio, 0.0, params_.ball.radius).State(launch_[0], launch_[1]);
  EXPECT_EQ(plan.v0, Eigen::Vector2d(start.segment<2>(physics::kVx)));
  EXPECT_EQ(plan.w0, Eigen::Vector3d(start.segment<3>(physics::kWx)));
  ASSERT_GE(plan.predicted_path.size(), 2u);
  EXPECT_LT((plan.predicted_path.front() - q_.from).norm(), 1e-12);
  EXPECT_EQ(plan.predicted_path.back(), plan.predicted_final);
  EXPECT_DOUBLE_EQ(plan.refined_miss_m, (plan.predicted_final - q_.to).norm());
  // Sampled every path_sample_dt or closer: a ball slower than its launch covers no more.
  const double longest = launch_[0] * options_.path_sample_dt;
  for (std::size_t i = 1; i < plan.predicted_path.size(); ++i) {
    EXPECT_LE((plan.predicted_path[i] - plan.predicted_path[i - 1]).norm(), longest) << i;
  }
}

TEST_F(PlanAssemblyTest, AnOkIsAStrokeThatGivesTheLaunch) {
  Aim({0.4, 0.5}, {1.8, 0.9});
  options_.refine = false;  // the closed form's launch judged as it is
  Shot shot(q_, held_, params_, options_);
  ShotPlan plan;
  Conclude(shot, launch_, Predict(shot, launch_, &plan), &plan);
  ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.reason;
  const physics::BallState given = physics::StrikeBall(plan.stroke, q_.from, params_);
  EXPECT_LT((given.segment<2>(physics::kVx) - plan.v0).norm(), 1e-9);
  EXPECT_LT((given.segment<3>(physics::kWx) - plan.w0).norm(), 1e-6);
}

TEST_F(PlanAssemblyTest, APathOffTheSurfaceIsUnreachable) {
  // Along the cushion, a millimetre from the surface's edge, unrefined: side spin of one sign
  // curves the path over the edge, of the other away from it.
  const double y = params_.ball.radius + 1e-3;
  options_.refine = false;
  for (const double side_spin : {25.0, -25.0}) {
    Aim({0.4, y}, {1.8, y}, side_spin);
    Shot shot(q_, held_, params_, options_);
    ShotPlan plan;
    Conclude(shot, launch_, Predict(shot, launch_, &plan), &plan);
    if (side_spin > 0.0) {
      EXPECT_EQ(plan.status, PlanStatus::kUnreachable);
      EXPECT_NE(plan.reason.find("cushion"), std::string::npos) << plan.reason;
    } else {
      EXPECT_EQ(plan.status, PlanStatus::kOk) << plan.reason;
    }
  }
}

TEST_F(PlanAssemblyTest, AMissBeyondTheAcceptableIsNotConverged) {
  Aim({0.4, 0.5}, {1.8, 0.9});
  options_.acceptable_miss = 1e-9;  // the closed form's launch, unrefined, misses by more
  Shot shot(q_, held_, params_, options_);
  ShotPlan plan;
  Conclude(shot, launch_, Predict(shot, launch_, &plan), &plan);
  EXPECT_EQ(plan.status, PlanStatus::kNotConverged);
  EXPECT_NE(plan.reason.find("mm from the target"), std::string::npos) << plan.reason;
}

}  // namespace
}  // namespace billiard::planner
