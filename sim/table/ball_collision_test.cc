// The ball-ball impact against the analytic truths of pool (Alciatore 2004, TP A.14 and the
// 30-degree rule of TP 3.1) and the conservation laws.
#include "sim/table/ball_collision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/table/ball_motion.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::kVy;
using physics::kWx;
using physics::kX;
using physics::MakeBallState;

constexpr double kDegree = M_PI / 180.0;

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }

// The cue ball at the origin moving along +x at speed v with spin (wx, wy, wz), and an object
// ball at rest touching it where a cut of `cut` radians sends it (line of centres at -cut).
std::pair<BallState, BallState> Cut(double cut, double v, double wx, double wy, double wz,
                                    double r) {
  const BallState cue = MakeBallState(0, 0, v, 0, wx, wy, wz);
  const BallState object =
      MakeBallState(2 * r * std::cos(cut), -2 * r * std::sin(cut), 0, 0, 0, 0, 0);
  return {cue, object};
}

double Heading(const BallState& s) { return std::atan2(s[kVy], s[kVx]); }

// Where a ball ends up heading once it rolls (the end of its sliding phase).
BallState Rolling(const ClothParameters& cloth, const BallState& s) {
  const MotionSegment m(cloth, 0.0, s);
  return m.phase() == MotionPhase::kSliding ? m.At(m.end_time()) : s;
}

physics::CollisionParameters Ideal() {
  physics::CollisionParameters c = Pool().collision;
  c.ball_restitution = 1.0;
  c.ball_friction_a = c.ball_friction_b = 0.0;
  return c;
}

TEST(BallBallImpact, HeadOnStunSendsTheObjectBallAtHalfOnePlusE) {
  const auto p = Pool();
  const double e = p.collision.ball_restitution;
  const auto [cue, object] = Cut(0.0, 2.0, 0, 0, 0, p.ball.radius);
  const BallBallImpulse hit = ResolveBallBallImpact(cue, object, p.ball, p.collision);
  EXPECT_NEAR(hit.b[kVx], (1 + e) / 2 * 2.0, 1e-14);
  EXPECT_NEAR(hit.a[kVx], (1 - e) / 2 * 2.0, 1e-14);
  EXPECT_EQ(hit.friction, 0.0);  // no slip between the balls, no friction
  EXPECT_EQ(hit.a.tail<3>().norm() + hit.b.tail<3>().norm(), 0.0);
}

TEST(BallBallImpact, HeadOnNaturalRollFollowsAtTwoSeventhsPlusTheRestitutionTerm) {
  // The cue ball keeps its top spin and (1 - e)/2 v, then rolls at 5/7 (1 - e)/2 v + 2/7 v; the
  // friction of the vertical slip takes a little of the top spin (TP A.14).
  const auto p = Pool();
  const double e = p.collision.ball_restitution;
  const double v = 1.5;
  const auto [cue, object] = Cut(0.0, v, 0, v / p.ball.radius, 0, p.ball.radius);
  const BallBallImpulse hit = ResolveBallBallImpact(cue, object, p.ball, p.collision);
  const BallState follow = Rolling(ClothParameters::From(p), hit.a);
  const double ideal = 5.0 / 7.0 * (1 - e) / 2 * v + 2.0 / 7.0 * v;
  // The contact points slip vertically at v: friction mu_b J_n (below the sticking impulse)
  // takes mu_b J_n / (2/5 m) from the surface speed r wy.
  const double lost = hit.friction_coefficient * hit.normal / (0.4 * p.ball.mass);
  EXPECT_NEAR(hit.friction, hit.friction_coefficient * hit.normal, 1e-15);
  EXPECT_NEAR(follow[kVx], ideal - 2.0 / 7.0 * lost, 1e-12);
  EXPECT_NEAR(follow[kVx], ideal, 0.1 * ideal);
  EXPECT_NEAR(follow[kVy], 0.0, 1e-15);
  // Without friction between the balls it is the ideal exactly.
  physics::CollisionParameters no_friction = p.collision;
  no_friction.ball_friction_a = no_friction.ball_friction_b = 0.0;
  const BallState ideal_follow =
      Rolling(ClothParameters::From(p), ResolveBallBallImpact(cue, object, p.ball, no_friction).a);
  EXPECT_NEAR(ideal_follow[kVx], ideal, 1e-12);
}

TEST(BallBallImpact, StunCutSeparatesAtNinetyDegreesLessTheThrow) {
  const auto p = Pool();
  for (double cut_degrees : {10.0, 30.0, 45.0, 60.0, 80.0}) {
    const double cut = cut_degrees * kDegree;
    const auto [cue, object] = Cut(cut, 1.0, 0, 0, 0, p.ball.radius);
    // Elastic and frictionless: exactly 90 degrees, the object ball along the line of centres.
    const BallBallImpulse ideal = ResolveBallBallImpact(cue, object, p.ball, Ideal());
    EXPECT_NEAR(Heading(ideal.a) - Heading(ideal.b), 90.0 * kDegree, 1e-12);
    EXPECT_NEAR(Heading(ideal.b), -cut, 1e-12);
    // With friction the object ball is thrown towards the cue ball's path by atan(J_t / J_n),
    // and restitution below 1 closes the angle further.
    const BallBallImpulse hit = ResolveBallBallImpact(cue, object, p.ball, p.collision);
    const double throw_angle = Heading(hit.b) + cut;
    EXPECT_NEAR(throw_angle, std::atan(hit.friction / hit.normal), 1e-12);
    EXPECT_GT(throw_angle, 0.0);
    const double separation = Heading(hit.a) - Heading(hit.b);
    EXPECT_LT(separation, 90.0 * kDegree - throw_angle + 1e-12) << cut_degrees;
    EXPECT_GT(separation, 80.0 * kDegree - throw_angle) << cut_degrees;
  }
}

TEST(BallBallImpact, NaturalRollHalfBallHitTurnsTheCueBallAboutThirtyDegrees) {
  // The 30-degree rule (Alciatore 2004, TP 3.1): elastic and frictionless, the rolling cue
  // ball's final path turns by atan(sin c cos c / (sin^2 c + 2/5)), 33.7 degrees at the
  // half-ball cut c = 30 degrees, and within 3 degrees of 30 from a quarter- to a
  // three-quarter-ball hit.
  const auto p = Pool();
  const ClothParameters cloth = ClothParameters::From(p);
  const double v = 1.0, r = p.ball.radius;
  for (double cut_degrees : {30.0, 14.5, 48.6}) {
    const double c = cut_degrees * kDegree;
    const auto [cue, object] = Cut(c, v, 0, v / r, 0, r);
    const BallState after = Rolling(cloth, ResolveBallBallImpact(cue, object, p.ball, Ideal()).a);
    const double expected =
        std::atan(std::sin(c) * std::cos(c) / (std::sin(c) * std::sin(c) + 0.4));
    EXPECT_NEAR(Heading(after), expected, 1e-9) << cut_degrees;
    EXPECT_NEAR(Heading(after), 30.0 * kDegree, 4.0 * kDegree) << cut_degrees;
  }
  // With the pool set's restitution and friction the half-ball hit stays near 30 degrees.
  const auto [cue, object] = Cut(30.0 * kDegree, v, 0, v / r, 0, r);
  const BallState real = Rolling(cloth, ResolveBallBallImpact(cue, object, p.ball, p.collision).a);
  EXPECT_NEAR(Heading(real), 30.0 * kDegree, 4.0 * kDegree);
}

TEST(BallBallImpact, MomentumIsConservedAndEnergyNeverRises) {
  const auto p = Pool();
  const double r = p.ball.radius, m = p.ball.mass;
  std::mt19937_64 rng(14);
  const auto uniform = [&](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53;
  };
  int impacts = 0;
  for (int k = 0; k < 10000; ++k) {
    const double angle = uniform(-M_PI, M_PI);
    const BallState a = MakeBallState(0, 0, uniform(-8, 8), uniform(-8, 8), uniform(-300, 300),
                                      uniform(-300, 300), uniform(-300, 300));
    const BallState b =
        MakeBallState(2 * r * std::cos(angle), 2 * r * std::sin(angle), uniform(-3, 3),
                      uniform(-3, 3), uniform(-100, 100), uniform(-100, 100), uniform(-100, 100));
    const BallBallImpulse hit = ResolveBallBallImpact(a, b, p.ball, p.collision);
    if (hit.normal == 0.0) continue;
    ++impacts;
    const Eigen::Vector2d before = a.segment<2>(kVx) + b.segment<2>(kVx);
    const Eigen::Vector2d after = hit.a.segment<2>(kVx) + hit.b.segment<2>(kVx);
    EXPECT_LT((after - before).norm(), 1e-14 * (1 + before.norm()));
    const double e0 = physics::KineticEnergy(a, m, r) + physics::KineticEnergy(b, m, r);
    const double e1 = physics::KineticEnergy(hit.a, m, r) + physics::KineticEnergy(hit.b, m, r);
    EXPECT_LE(e1, e0 * (1 + 1e-14));
    // The balls part: their centres no longer close.
    const Eigen::Vector2d n = (b.segment<2>(kX) - a.segment<2>(kX)).normalized();
    EXPECT_GE((hit.b.segment<2>(kVx) - hit.a.segment<2>(kVx)).dot(n), 0.0);
  }
  EXPECT_GT(impacts, 4000);
}

TEST(BallBallImpact, BallsThatDoNotCloseAreLeftAlone) {
  const auto p = Pool();
  const auto [cue, object] = Cut(0.3, -1.0, 5, 5, 5, p.ball.radius);
  const BallBallImpulse hit = ResolveBallBallImpact(cue, object, p.ball, p.collision);
  EXPECT_EQ(hit.normal, 0.0);
  EXPECT_EQ(hit.a, cue);
  EXPECT_EQ(hit.b, object);
}

TEST(BallBallImpact, FrictionFallsWithTheSlipSpeedAsAlciatoresFit) {
  // TP A.14: mu_b = 9.951e-3 + 0.108 exp(-1.088 v), about 0.11 when slow, 0.06 at 0.5 m/s.
  const auto c = Pool().collision;
  EXPECT_NEAR(BallBallFriction(c, 0.0), 0.117951, 1e-6);
  EXPECT_NEAR(BallBallFriction(c, 0.5), 9.951e-3 + 0.108 * std::exp(-0.544), 1e-12);
  EXPECT_GT(BallBallFriction(c, 0.1), BallBallFriction(c, 1.0));
}

}  // namespace
}  // namespace billiard::table
