// The table's closed-form motion against the single-ball closed form it extends (Jaroukh 2019,
// sim/physics/closed_form.h) and against the 5-DOF model's pivot friction (Kudra et al. 2016).
#include "sim/table/ball_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/params/parameter_sets.h"
#include "sim/physics/closed_form.h"
#include "sim/physics/simulator.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::kWz;
using physics::kX;
using physics::MakeBallState;

// The phases of a ball from `initial` until it rests.
std::vector<MotionSegment> FollowToRest(const ClothParameters& cloth, const BallState& initial) {
  std::vector<MotionSegment> phases{MotionSegment(cloth, 0.0, initial)};
  while (std::isfinite(phases.back().end_time())) {
    const MotionSegment& last = phases.back();
    phases.emplace_back(cloth, last.end_time(), last.At(last.end_time()));
  }
  return phases;
}

BallState StateAt(const std::vector<MotionSegment>& phases, double t) {
  for (const MotionSegment& m : phases) {
    if (t <= m.end_time()) return m.At(t);
  }
  return phases.back().At(t);
}

TEST(BallMotion, WithoutSideSpinItIsTheSingleBallClosedForm) {
  const physics::ModelParameters pool = params::LoadParameters("pool");
  const ClothParameters cloth = ClothParameters::From(pool);
  const physics::ClosedFormParameters single = physics::ClosedFormParameters::From(pool);
  for (const BallState& initial :
       {MakeBallState(0.3, 0.4, 2.0, 0.5, 0.0, 0.0, 0.0),                // stun
        MakeBallState(0.3, 0.4, 1.0, -1.0, 60.0, 40.0, 0.0),             // draw
        MakeBallState(0.3, 0.4, 0.0, 1.5, -80.0, 0.0, 0.0),              // over-spun follow
        MakeBallState(0.3, 0.4, 0.7, 0.0, 0.0, 0.7 / 0.028575, 0.0)}) {  // natural roll
    const auto phases = FollowToRest(cloth, initial);
    const physics::ClosedFormTrajectory reference(single, initial);
    EXPECT_NEAR(phases.back().start_time(), reference.stop_time(), 1e-12);
    for (double t = 0.0; t < reference.stop_time() + 1.0; t += 0.01) {
      const BallState a = StateAt(phases, t);
      const BallState b = reference.At(t);
      EXPECT_LT((a.head<6>() - b.head<6>()).cwiseAbs().maxCoeff(), 1e-12) << "t = " << t << "\n"
                                                                          << a.transpose() << "\n"
                                                                          << b.transpose();
    }
  }
}

TEST(BallMotion, PhasesFollowSlidingRollingSpinningRest) {
  const ClothParameters cloth = ClothParameters::From(params::LoadParameters("pool"));
  const auto phases = FollowToRest(cloth, MakeBallState(0, 0, 0.2, 0.0, 0.0, 0.0, 40.0));
  ASSERT_EQ(phases.size(), 4u);
  EXPECT_EQ(phases[0].phase(), MotionPhase::kSliding);
  EXPECT_EQ(phases[1].phase(), MotionPhase::kRolling);
  EXPECT_EQ(phases[2].phase(), MotionPhase::kSpinning);
  EXPECT_EQ(phases[3].phase(), MotionPhase::kStationary);
  // The spin runs down at its constant rate from the start, through every phase.
  EXPECT_NEAR(phases[3].start_time(), 40.0 / cloth.spin_decel, 1e-12);
  EXPECT_EQ(phases[3].start_state().tail<5>().norm(), 0.0);
}

TEST(BallMotion, EnergyNeverRisesAndEveryPhaseEndsWhereTheNextBegins) {
  const physics::ModelParameters pool = params::LoadParameters("pool");
  const ClothParameters cloth = ClothParameters::From(pool);
  const auto phases = FollowToRest(cloth, MakeBallState(0, 0, 2.0, 1.0, 30.0, -90.0, -25.0));
  double energy = INFINITY;
  for (double t = 0.0; t < phases.back().start_time() + 0.1; t += 1e-3) {
    const double e = physics::KineticEnergy(StateAt(phases, t), pool.ball.mass, pool.ball.radius);
    EXPECT_LE(e, energy * (1.0 + 1e-14)) << "t = " << t;
    energy = e;
  }
  for (std::size_t k = 1; k < phases.size(); ++k) {
    const BallState end = phases[k - 1].At(phases[k - 1].end_time());
    EXPECT_EQ(phases[k].start_state().head<2>(), end.head<2>());
  }
}

TEST(BallMotion, SpinDecaysAsTheFiveDofModelsPivotFriction) {
  // A ball spinning in place: in the approximate 5-DOF model, dwz/dt = -5/2 g a mu Ms / r^2
  // with Ms = (3 pi/16 bM ws) / sqrt(bM^2 ws^2 + eps_t^2), 3 pi / 16 once ws >> eps_t / bM.
  const physics::ModelParameters pool = params::LoadParameters("pool");
  const ClothParameters cloth = ClothParameters::From(pool);
  const BallState spin = MakeBallState(0.5, 0.5, 0.0, 0.0, 0.0, 0.0, 20.0);
  const MotionSegment closed(cloth, 0.0, spin);
  ASSERT_EQ(closed.phase(), MotionPhase::kSpinning);
  for (double t : {0.3, 0.8, 1.5}) {
    const double five_dof = physics::Simulate(pool, spin, t).final_state[kWz];
    EXPECT_NEAR(closed.At(t)[kWz], five_dof, 1e-3 * 20.0) << "t = " << t;
  }
  EXPECT_NEAR(cloth.spin_decel, 9.91, 0.01);  // about 10 rad/s^2 (sim/params/pool.json)
}

TEST(BallMotion, AStateOnItsPhaseBoundaryTakesTheLaterPhase) {
  const ClothParameters cloth = ClothParameters::From(params::LoadParameters("pool"));
  const double r = cloth.radius;
  EXPECT_EQ(MotionSegment(cloth, 0, MakeBallState(0, 0, 1, 0, 0, 1 / r, 0)).phase(),
            MotionPhase::kRolling);
  EXPECT_EQ(MotionSegment(cloth, 0, MakeBallState(0, 0, 0, 0, 0, 0, 1)).phase(),
            MotionPhase::kSpinning);
  const MotionSegment still(cloth, 2.0, MakeBallState(0.1, 0.2, 0, 0, 0, 0, 0));
  EXPECT_EQ(still.phase(), MotionPhase::kStationary);
  EXPECT_TRUE(std::isinf(still.end_time()));
  EXPECT_EQ(still.At(1e9).head<2>(), Eigen::Vector2d(0.1, 0.2));
}

}  // namespace
}  // namespace billiard::table
