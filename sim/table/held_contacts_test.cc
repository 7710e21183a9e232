// The held-contact solve against the closed forms of its textbook cases: a sliding ball pushing
// one at rest, a rolling ball pushing a sliding one, a ball driven into a cushion by its spin; a
// slow closing met plastically without a gain of energy; parting bodies left alone.
#include "sim/table/held_contacts.h"

#include <gtest/gtest.h>

#include "sim/params/parameter_sets.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::MakeBallState;

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }

TEST(HeldContacts, ASlidingBallPushingOneAtRestMovesItAtTheCommonAcceleration) {
  // The pusher stopped with top spin (a follow shot's cue ball after a full hit), so the cloth
  // drives it on at mu g; the ball it touches rests. Held, both move with one acceleration: the pusher's
  // mu g - N against the pushed ball's 5/7 (N - mu_r g), N = 7/12 (mu g + 5/7 mu_r g).
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double r = p.ball.radius, g = cloth.gravity, mu = cloth.mu_slide, mu_r = cloth.mu_roll;
  const BallState pusher = MakeBallState(1.0, 0.5, 0.0, 0, 0, 1.0 / r, 0);
  const BallState rest = MakeBallState(1.0 + 2 * r, 0.5, 0, 0, 0, 0, 0);
  const HeldSolution held =
      SolveHeldContacts(cloth, {pusher, rest}, {{0, 1, Eigen::Vector2d::UnitX(), 0.0}});
  const double n = 7.0 / 12.0 * (mu * g + 5.0 / 7.0 * mu_r * g);
  EXPECT_NEAR(held.normal_forces[0], n, 1e-10);
  EXPECT_NEAR(held.accelerations[0].x(), mu * g - n, 1e-10);
  EXPECT_NEAR(held.accelerations[1].x(), mu * g - n, 1e-10);
  EXPECT_NEAR(held.accelerations[0].y(), 0.0, 1e-15);
  EXPECT_LE(held.residual, 1e-11);
}

TEST(HeldContacts, ARollingBallPushingASlidingOneSharesItsDeceleration) {
  // Both at 1 m/s, touching, the front one sliding without spin (the cloth brakes it at mu g),
  // the back one rolling: 5/7 of the force moves a rolling ball, so the pair decelerates at
  // (5/12) mu g (plus the rolling ball's share of its rolling resistance).
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double r = p.ball.radius, g = cloth.gravity, mu = cloth.mu_slide, mu_r = cloth.mu_roll;
  const BallState back = MakeBallState(1.0, 0.5, 1.0, 0, 0, 1.0 / r, 0);
  const BallState front = MakeBallState(1.0 + 2 * r, 0.5, 1.0, 0, 0, 0, 0);
  const HeldSolution held =
      SolveHeldContacts(cloth, {back, front}, {{0, 1, Eigen::Vector2d::UnitX(), 0.0}});
  const double n = 7.0 / 12.0 * (mu * g - 5.0 / 7.0 * mu_r * g);
  EXPECT_NEAR(held.normal_forces[0], n, 1e-10);
  EXPECT_NEAR(held.accelerations[0].x(), -mu * g + n, 1e-10);
  EXPECT_NEAR(held.accelerations[1].x(), -mu * g + n, 1e-10);
  EXPECT_NEAR(held.accelerations[0].x(), -5.0 / 12.0 * mu * g - 5.0 / 12.0 * mu_r * g, 1e-10);
}

TEST(HeldContacts, ABallDrivenIntoACushionSlidesAlongItAgainstTheCushionsFriction) {
  // Against the lower cushion (the contact normal -y from the ball), moving along it at 1 m/s
  // with its slip partly into it: the cushion takes the normal part of the cloth's friction,
  // mu g u_y / |u|, and its own friction mu_w N brakes the ball along it.
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double r = p.ball.radius, g = cloth.gravity, mu = cloth.mu_slide;
  const double mu_w = p.collision.cushion_friction;
  BallState s = MakeBallState(1.0, r, 1.0, 0, 0, 0, 0);
  s[physics::kWx] = 10.0;  // slip u_y = r wx > 0: the friction, -mu g u_hat, points into the cushion
  const Eigen::Vector2d u(1.0, r * 10.0);
  const HeldSolution held =
      SolveHeldContacts(cloth, {s}, {{0, -1, -Eigen::Vector2d::UnitY(), mu_w}});
  const double n = mu * g * u.normalized().y();
  EXPECT_NEAR(held.normal_forces[0], n, 1e-12);
  EXPECT_NEAR(held.accelerations[0].y(), 0.0, 1e-12);
  EXPECT_NEAR(held.accelerations[0].x(), -mu * g * u.normalized().x() - mu_w * n, 1e-12);
}

TEST(HeldContacts, ASlowClosingMeetsPlasticallyAndLosesEnergy) {
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double r = p.ball.radius;
  // A rolling ball at 0.2 m/s catching one rolling at 0.19996 m/s (closing at 4e-5 m/s).
  const BallState a = MakeBallState(1.0, 0.5, 0.2, 0, 0, 0.2 / r, 0);
  const BallState b = MakeBallState(1.0 + 2 * r, 0.5, 0.19996, 0, 0, 0.19996 / r, 0);
  const HeldSolution held =
      SolveHeldContacts(cloth, {a, b}, {{0, 1, Eigen::Vector2d::UnitX(), 0.0}});
  EXPECT_NEAR(held.states[0][kVx], held.states[1][kVx], 1e-12);
  // Both roll on, with the momentum they had: equal masses, the mean.
  EXPECT_NEAR(held.states[0][kVx], 0.19998, 1e-12);
  EXPECT_NEAR(held.states[0][physics::kWy], held.states[0][kVx] / r, 1e-9);
  const auto energy = [&](const BallState& s) {
    return physics::KineticEnergy(s, p.ball.mass, r);
  };
  EXPECT_LT(energy(held.states[0]) + energy(held.states[1]), energy(a) + energy(b));
  // Rolling together, they decelerate alike: no force.
  EXPECT_EQ(held.normal_forces[0], 0.0);
}

TEST(HeldContacts, PartingBodiesAreLeftAlone) {
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double r = p.ball.radius;
  // The back ball has over-follow (driven forward at mu g), but the front one leaves at 1 m/s.
  const BallState back = MakeBallState(1.0, 0.5, 0.0, 0, 0, 1.0 / r, 0);
  const BallState front = MakeBallState(1.0 + 2 * r, 0.5, 1.0, 0, 0, 1.0 / r, 0);
  const HeldSolution held =
      SolveHeldContacts(cloth, {back, front}, {{0, 1, Eigen::Vector2d::UnitX(), 0.0}});
  EXPECT_EQ(held.normal_forces[0], 0.0);
  EXPECT_EQ(held.states[1], front);
  EXPECT_NEAR(held.accelerations[0].x(), cloth.mu_slide * cloth.gravity, 1e-12);
}

}  // namespace
}  // namespace billiard::table
