// The cue strike model against the collision laws it must reduce to, and its inverse.
#include "sim/physics/cue_strike.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

TEST(CueStrike, CentreHitIsAOneDimensionalCollision) {
  ModelParameters p = testing::PaperParameters();
  p.cue.tip_restitution = 1.0;
  const BallState s = StrikeBall({3.0, 0.0, 0.0, 0.0, 0.0}, {0.5, 0.4}, p);
  // Elastic collision of masses M (moving at V) and m (at rest): v = 2 M V / (M + m).
  EXPECT_NEAR(s[kVx], 2 * p.cue.mass * 3.0 / (p.cue.mass + p.ball.mass), 1e-12);
  EXPECT_EQ(s[kVy], 0.0);
  EXPECT_EQ(s.tail<3>().norm(), 0.0);
  EXPECT_EQ(s[kX], 0.5);
}

TEST(CueStrike, TipTwoFifthsOfTheRadiusAboveCentreGivesNaturalRoll) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  const BallState s = StrikeBall({2.0, 0.7, 0.0, 0.4 * r, 0.0}, {0, 0}, p);
  // Contact point velocity v + w x (-r z) vanishes.
  EXPECT_NEAR(s[kVx] - r * s[kWy], 0.0, 1e-12);
  EXPECT_NEAR(s[kVy] + r * s[kWx], 0.0, 1e-12);
  EXPECT_EQ(s[kWz], 0.0);
}

TEST(CueStrike, RightEnglishSpinsTheBallCounterclockwiseSeenFromAbove) {
  const ModelParameters p = testing::PaperParameters();
  const BallState s = StrikeBall({2.0, 0.3, 0.3 * p.ball.radius, 0.0, 0.0}, {0, 0}, p);
  EXPECT_GT(s[kWz], 0.0);
  EXPECT_NEAR(s[kWx] * s[kVx] + s[kWy] * s[kVy], 0.0, 1e-12);  // no spin about the travel
}

// With a perfectly elastic tip, a level stroke at any offset keeps the kinetic energy of cue and
// ball: 1/2 M V^2 = 1/2 M V'^2 + 1/2 m v^2 + 1/2 I w^2, the cue slowed by the impulse,
// V' = V - J / M.
TEST(CueStrike, ElasticStrikeConservesTheEnergyOfCueAndBallAtAnyOffset) {
  ModelParameters p = testing::PaperParameters();
  p.cue.tip_restitution = 1.0;
  const double r = p.ball.radius, m = p.ball.mass, big_m = p.cue.mass;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 500; ++i) {
    const double angle = M_PI * u(rng), offset = 0.95 * r * std::abs(u(rng));
    const CueStroke stroke{0.2 + 6 * std::abs(u(rng)), 3 * u(rng), offset * std::cos(angle),
                           offset * std::sin(angle), 0.0};
    const BallState s = StrikeBall(stroke, {0, 0}, p);
    const double impulse = m * s.segment<2>(kVx).norm();
    const double cue_after = stroke.speed - impulse / big_m;
    const double before = 0.5 * big_m * stroke.speed * stroke.speed;
    const double after = 0.5 * big_m * cue_after * cue_after + KineticEnergy(s, m, r);
    EXPECT_NEAR(after / before, 1.0, 1e-12) << "offset " << offset / r << " r";
  }
}

// Alciatore, TP A.30: momentum and restitution at the tip give the ball
// v = (1 + e) V / (1 + m / M + 5/2 q^2), q = b / r the tip offset.
TEST(CueStrike, BallSpeedIsAlciatoresLawAtEveryOffset) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius, m = p.ball.mass, big_m = p.cue.mass;
  const double e = p.cue.tip_restitution, cue_speed = 2.0;
  for (double q : {0.0, 0.1, 0.25, 0.4, 0.5}) {
    const BallState s = StrikeBall({cue_speed, 0.0, 0.0, q * r, 0.0}, {0, 0}, p);
    const double expected = (1 + e) * cue_speed / (1 + m / big_m + 2.5 * q * q);
    EXPECT_NEAR(s.segment<2>(kVx).norm(), expected, 1e-12 * expected) << "q = " << q;
  }
}

TEST(CueStrike, BallNeverGainsMoreEnergyThanTheCueBrings) {
  const ModelParameters p = testing::PaperParameters();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double r = p.ball.radius;
    const CueStroke stroke{4.0 * std::abs(u(rng)), 3 * u(rng), 0.6 * r * u(rng), 0.6 * r * u(rng),
                           0.7 * std::abs(u(rng))};
    const BallState s = StrikeBall(stroke, {0, 0}, p);
    // The horizontal part only: the table takes the vertical momentum.
    EXPECT_LE(KineticEnergy(s, p.ball.mass, r), 0.5 * p.cue.mass * stroke.speed * stroke.speed);
  }
}

TEST(CueStrike, InverseRecoversTheStroke) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const double angle = M_PI * u(rng), offset = p.cue.max_tip_offset * r * std::abs(u(rng));
    const CueStroke stroke{0.5 + 5 * std::abs(u(rng)), 3 * u(rng), offset * std::cos(angle),
                           offset * std::sin(angle), i % 3 == 0 ? 0.0 : 0.5 * std::abs(u(rng))};
    const BallState s = StrikeBall(stroke, {0, 0}, p);
    const StrokeSolution back = StrokeFor(s.segment<2>(kVx), s.tail<3>(), p);
    ASSERT_TRUE(back.ok) << back.reason;
    EXPECT_NEAR(back.stroke.speed, stroke.speed, 1e-9);
    EXPECT_NEAR(std::remainder(back.stroke.heading - stroke.heading, 2 * M_PI), 0.0, 1e-12);
    EXPECT_NEAR(back.stroke.tip_side, stroke.tip_side, 1e-12);
    EXPECT_NEAR(back.stroke.tip_height, stroke.tip_height, 1e-12);
    EXPECT_NEAR(back.stroke.elevation, stroke.elevation, 1e-9);
  }
}

TEST(CueStrike, InverseRefusesWhatNoStrokeCanGive) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  const auto refused = [&](Eigen::Vector2d v, Eigen::Vector3d w) {
    const StrokeSolution s = StrokeFor(v, w, p);
    EXPECT_FALSE(s.ok);
    EXPECT_FALSE(s.reason.empty());
    return s.reason;
  };
  refused({NAN, 1}, {0, 0, 0});
  refused({0, 0}, {0, 0, 10});
  refused({1, 0}, {5, 0, 0});        // spin about the travel without side spin
  refused({1, 0}, {0, 2.0 / r, 0});  // top spin of 2 v / r: offset 0.8 r
  EXPECT_NE(refused({20, 0}, {0, 0, 0}).find("cue speed"), std::string::npos);
  EXPECT_TRUE(StrokeFor({1, 0}, {0, 1.0 / r, 0}, p).ok);  // natural roll
}

TEST(CueStrike, StrikeRejectsImpossibleStrokes) {
  const ModelParameters p = testing::PaperParameters();
  EXPECT_THROW(StrikeBall({NAN, 0, 0, 0, 0}, {0, 0}, p), std::invalid_argument);
  EXPECT_THROW(StrikeBall({1, 0, p.ball.radius, 0, 0}, {0, 0}, p), std::invalid_argument);
  EXPECT_THROW(StrikeBall({1, 0, 0, 0, M_PI / 2}, {0, 0}, p), std::invalid_argument);
  EXPECT_THROW(StrikeBall({-1, 0, 0, 0, 0}, {0, 0}, p), std::invalid_argument);
}

TEST(CueStrike, LaunchSpeedRangeIsWhereStrokeForSucceeds) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  const Eigen::Vector2d e(0.6, 0.8);
  // A launch along e with R w = k v across the line and side spin wz.
  const auto stroke_ok = [&](double speed, double k, double wz) {
    const Eigen::Vector3d w(-k * speed / r * e.y(), k * speed / r * e.x(), wz);
    return StrokeFor(speed * e, w, p).ok;
  };
  for (auto [k, wz] : {std::pair{1.0, 0.0}, {-1.0, 40.0}, {0.0, -120.0}, {0.5, 300.0}}) {
    const LaunchSpeedRange range = LaunchSpeedsFor(k, wz, p);
    ASSERT_LT(range.min, range.max) << k << " " << wz;
    EXPECT_TRUE(stroke_ok(range.max * (1 - 1e-9), k, wz)) << k << " " << wz;
    EXPECT_FALSE(stroke_ok(range.max * (1 + 1e-6), k, wz)) << k << " " << wz;
    if (wz != 0.0) {
      EXPECT_TRUE(stroke_ok(range.min * (1 + 1e-9), k, wz)) << k << " " << wz;
      EXPECT_FALSE(stroke_ok(range.min * (1 - 1e-6), k, wz)) << k << " " << wz;
    } else {
      EXPECT_EQ(range.min, 0.0);
    }
  }
  // More draw than half a radius of tip offset gives (R w / v = 5/2 q): no stroke at all.
  const LaunchSpeedRange none = LaunchSpeedsFor(-1.3, 0.0, p);
  EXPECT_GT(none.min, none.max);
}

}  // namespace
}  // namespace billiard::physics
