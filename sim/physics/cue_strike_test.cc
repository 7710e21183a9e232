// The cue strike model against the collision laws it must reduce to, and its inverse.
#include "sim/physics/cue_strike.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
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

// A level stroke's impulse, J = m v (the table takes none), split along the cue axis and its
// right, and the contact point of the tip on the ball.
struct LevelImpact {
  double axial, side;
  Eigen::Vector3d axis, right, contact;
};
LevelImpact ImpactOf(const CueStroke& stroke, const BallState& s, const ModelParameters& p) {
  const double r = p.ball.radius;
  LevelImpact k;
  k.axis = {std::cos(stroke.heading), std::sin(stroke.heading), 0.0};
  k.right = k.axis.cross(Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d v(s[kVx], s[kVy], 0.0);
  k.axial = p.ball.mass * v.dot(k.axis);
  k.side = p.ball.mass * v.dot(k.right);
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height) / r;
  k.contact = stroke.tip_side * k.right + stroke.tip_height * Eigen::Vector3d::UnitZ() -
              r * std::sqrt(1.0 - offset * offset) * k.axis;
  return k;
}

CueStroke RandomLevelStroke(std::mt19937& rng, const ModelParameters& p) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double angle = M_PI * u(rng), offset = 0.95 * p.ball.radius * std::abs(u(rng));
  return {0.2 + 6 * std::abs(u(rng)), 3 * u(rng), offset * std::cos(angle),
          offset * std::sin(angle), 0.0};
}

// The two conditions of the impact (TP A.30, A.31), checked on the ball's launch: along the cue
// axis the ball's contact point leaves the tip at e V, the cue slowed by J_c / M; sideways the
// tip end (pushed by -J_n) moves with the ball's contact point.
TEST(CueStrike, TipEndMovesWithTheContactPointSidewaysAndRestitutesAlongTheAxis) {
  const ModelParameters p = testing::PaperParameters();
  const double e = p.cue.tip_restitution;
  std::mt19937 rng(7);
  for (int i = 0; i < 500; ++i) {
    const CueStroke stroke = RandomLevelStroke(rng, p);
    const BallState s = StrikeBall(stroke, {0, 0}, p);
    const LevelImpact k = ImpactOf(stroke, s, p);
    const Eigen::Vector3d v(s[kVx], s[kVy], 0.0), w = s.tail<3>();
    const Eigen::Vector3d contact_velocity = v + w.cross(k.contact);
    const double cue_after = stroke.speed - k.axial / p.cue.mass;
    EXPECT_NEAR(contact_velocity.dot(k.axis) - cue_after, e * stroke.speed, 1e-12 * stroke.speed);
    EXPECT_NEAR(contact_velocity.dot(k.right), -k.side / p.cue.end_mass, 1e-12 * stroke.speed);
    // And the spin is the moment of that impulse: P x J = I w.
    const Eigen::Vector3d moment = k.contact.cross(k.axial * k.axis + k.side * k.right);
    EXPECT_LT((moment - 0.4 * p.ball.mass * p.ball.radius * p.ball.radius * w).norm(),
              1e-12 * moment.norm() + 1e-300);
  }
}

// With a perfectly elastic tip, a level stroke at any offset keeps the kinetic energy of cue, end
// mass and ball: 1/2 M V^2 = 1/2 M V'^2 + 1/2 m_e u^2 + 1/2 m v^2 + 1/2 I w^2, the cue slowed by
// the axial impulse, V' = V - J_c / M, the end mass pushed sideways, u = -J_n / m_e. With e < 1
// the impact takes (1 - e) V J_c / 2: the relative speed along the axis, V, drops to -e V.
TEST(CueStrike, StrikeKeepsTheEnergyOfCueEndMassAndBallUpToTheTipsRestitution) {
  for (double e : {1.0, 0.75, 0.0}) {
    ModelParameters p = testing::PaperParameters();
    p.cue.tip_restitution = e;
    const double m = p.ball.mass, big_m = p.cue.mass, m_e = p.cue.end_mass;
    std::mt19937 rng(5);
    for (int i = 0; i < 500; ++i) {
      const CueStroke stroke = RandomLevelStroke(rng, p);
      const BallState s = StrikeBall(stroke, {0, 0}, p);
      const LevelImpact k = ImpactOf(stroke, s, p);
      const double cue_after = stroke.speed - k.axial / big_m, end_after = -k.side / m_e;
      const double before = 0.5 * big_m * stroke.speed * stroke.speed;
      const double after = 0.5 * big_m * cue_after * cue_after + 0.5 * m_e * end_after * end_after +
                           KineticEnergy(s, m, p.ball.radius);
      const double loss = 0.5 * (1.0 - e) * stroke.speed * k.axial;
      EXPECT_NEAR((after + loss) / before, 1.0, 1e-12) << "e " << e << ", stroke " << i;
    }
  }
}

// Alciatore, TP A.31, the squirt angle of a level stroke with the tip b right of centre:
// tan(alpha) = 5/2 (b/R) sqrt(1 - (b/R)^2) / (1 + m/m_e + 5/2 (1 - (b/R)^2)), to the left.
double TpA31SquirtAngle(double q, double ball_mass, double end_mass) {
  return std::atan(2.5 * q * std::sqrt(1 - q * q) / (1 + ball_mass / end_mass + 2.5 * (1 - q * q)));
}

TEST(CueStrike, SquirtAngleIsAlciatoresTpA31) {
  ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  // Low-deflection to standard shafts (about 5-7 g and 10-12 g).
  for (double end_mass : {0.005, 0.0075, 0.010, 0.012}) {
    p.cue.end_mass = end_mass;
    for (double q : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.9}) {
      EXPECT_NEAR(SquirtAngle(q * r, p), TpA31SquirtAngle(q, p.ball.mass, end_mass), 1e-15)
          << "m_e " << end_mass << ", q " << q;
    }
  }
  // pooltool's check of its TP A.31 squirt (Kiefl, tests/physics/resolve/ball_stick/
  // test_squirt.py): m / m_e = 20 and a fifth of the radius to the side give 1.19936 degrees.
  p.cue.end_mass = p.ball.mass / 20;
  EXPECT_NEAR(SquirtAngle(0.2 * r, p), 1.1993583313332898 * M_PI / 180, 1e-15);
  EXPECT_THROW(SquirtAngle(r, p), std::invalid_argument);
}

// Right english sends the ball left of the heading, by TP A.31's angle, at any heading; left
// english mirrors it; a centred or purely vertical offset leaves along the heading.
TEST(CueStrike, BallLeavesAlongTheHeadingTurnedByTheSquirt) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  for (double heading : {0.0, 0.4, 2.0, -2.9}) {
    for (double q : {-0.5, -0.2, 0.0, 0.1, 0.3, 0.5}) {
      const BallState s = StrikeBall({2.0, heading, q * r, 0.0, 0.0}, {0, 0}, p);
      const double turn = std::remainder(std::atan2(s[kVy], s[kVx]) - heading, 2 * M_PI);
      EXPECT_NEAR(turn, TpA31SquirtAngle(q, p.ball.mass, p.cue.end_mass), 1e-14)
          << "heading " << heading << ", q " << q;
      if (q > 0) {
        EXPECT_GT(turn, 0.0);
      }
    }
  }
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const CueStroke stroke{4 * std::abs(u(rng)), 3 * u(rng), 0.0, 0.9 * r * u(rng),
                           1.4 * std::abs(u(rng))};
    const BallState s = StrikeBall(stroke, {0, 0}, p);
    EXPECT_NEAR(std::remainder(std::atan2(s[kVy], s[kVx]) - stroke.heading, 2 * M_PI), 0.0, 1e-15);
  }
}

// Mirroring the stroke in the cue's vertical plane (tip_side -> -tip_side) mirrors the launch:
// along x, (vx, vy) -> (vx, -vy) and the spin, an axial vector, (wx, wy, wz) -> (-wx, wy, -wz).
TEST(CueStrike, SquirtIsSymmetricInTheSideOffset) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const CueStroke right{0.5 + 4 * std::abs(u(rng)), 0.0, 0.6 * r * u(rng), 0.6 * r * u(rng),
                          0.8 * std::abs(u(rng))};
    CueStroke left = right;
    left.tip_side = -right.tip_side;
    const BallState a = StrikeBall(right, {0, 0}, p), b = StrikeBall(left, {0, 0}, p);
    const Eigen::Matrix<double, 5, 1> mirrored(a[kVx], -a[kVy], -a[kWx], a[kWy], -a[kWz]);
    EXPECT_LT((b.tail<5>() - mirrored).norm(), 1e-13 * a.tail<5>().norm());
    EXPECT_EQ(SquirtAngle(-right.tip_side, p), -SquirtAngle(right.tip_side, p));
  }
}

// A heavier tip end is harder to push aside: the squirt grows with the end mass, towards the
// limit of a tip end that does not move sideways, tan(alpha) = 5/2 q sqrt(1-q^2)/(1 + 5/2 (1-q^2)).
TEST(CueStrike, SquirtGrowsWithTheEndMass) {
  ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  for (double q : {0.1, 0.3, 0.5}) {
    double previous = 0.0;
    for (double end_mass : {0.002, 0.005, 0.007, 0.010, 0.012, 0.05, 1.0}) {
      p.cue.end_mass = end_mass;
      const double alpha = SquirtAngle(q * r, p);
      EXPECT_GT(alpha, previous) << "m_e " << end_mass << ", q " << q;
      previous = alpha;
    }
    p.cue.end_mass = 1e9;
    EXPECT_NEAR(std::tan(SquirtAngle(q * r, p)),
                2.5 * q * std::sqrt(1 - q * q) / (1 + 2.5 * (1 - q * q)), 1e-9);
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

// Without a side offset an elevated cue leaves no spin about the travel, so the launch does not
// say the elevation: given it as the impulse's slope, the inverse recovers the stroke (a smaller
// tip offset and a faster cue than the level stroke of the same launch).
TEST(CueStrike, InverseAtAGivenSlopeRecoversAnElevatedStrokeWithoutSide) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  for (const double elevation : {0.05, 0.2, 0.6}) {
    for (const double height : {-0.3 * r, 0.0, 0.25 * r}) {
      const CueStroke stroke{2.0, 0.7, 0.0, height, elevation};
      BallState s = StrikeBall(stroke, {0, 0}, p);
      // No side spin, as a planned launch has it: the strike leaves rounding's 1e-17 rad/s.
      ASSERT_LT(std::abs(s[kWz]), 1e-12);
      s[kWz] = 0.0;
      const StrokeSolution back = StrokeFor(s.segment<2>(kVx), s.tail<3>(), p, std::tan(elevation));
      ASSERT_TRUE(back.ok) << back.reason;
      EXPECT_NEAR(back.stroke.speed, stroke.speed, 1e-9);
      EXPECT_NEAR(back.stroke.tip_height, height, 1e-12);
      EXPECT_NEAR(back.stroke.elevation, elevation, 1e-12);
      const StrokeSolution level = StrokeFor(s.segment<2>(kVx), s.tail<3>(), p);
      ASSERT_TRUE(level.ok) << level.reason;
      EXPECT_EQ(level.stroke.elevation, 0.0);
      EXPECT_LE(std::abs(height), std::abs(level.stroke.tip_height) + 1e-15);
    }
  }
  EXPECT_FALSE(StrokeFor({1.0, 0.0}, {0.0, 10.0, 0.0}, p, -0.1).ok);
}

// Launches asked for directly, with top or draw, side spin and spin about the travel (an
// elevated cue): the stroke StrokeFor returns launches exactly them, its heading off the launch
// by the squirt.
TEST(CueStrike, StrokeForLaunchesTheAskedVelocityAndSpin) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int squirted = 0;
  for (int i = 0; i < 500; ++i) {
    const double speed = 0.3 + 2.7 * std::abs(u(rng)), direction = M_PI * u(rng);
    const Eigen::Vector3d e(std::cos(direction), std::sin(direction), 0.0);
    const double wz = 0.5 * speed / r * u(rng);
    const double about_travel = i % 3 == 0 ? 0.0 : 0.6 * std::abs(u(rng)) * wz;
    const Eigen::Vector3d w0 = u(rng) * speed / r * Eigen::Vector3d::UnitZ().cross(e) +
                               wz * Eigen::Vector3d::UnitZ() + about_travel * e;
    const Eigen::Vector2d v0 = speed * e.head<2>();
    const StrokeSolution stroke = StrokeFor(v0, w0, p);
    ASSERT_TRUE(stroke.ok) << stroke.reason;
    const BallState s = StrikeBall(stroke.stroke, {0, 0}, p);
    EXPECT_LT((s.segment<2>(kVx) - v0).norm(), 1e-12 * speed) << i;
    EXPECT_LT((s.tail<3>() - w0).norm(), 1e-12 * speed / r) << i;
    if (std::abs(std::remainder(stroke.stroke.heading - direction, 2 * M_PI)) > 1e-3) ++squirted;
  }
  EXPECT_GT(squirted, 100);  // the side spins are large enough to turn the cue visibly
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
  const ModelParameters paper = testing::PaperParameters();
  // A tip allowed to 0.95 r: the slowest launch with wz = 465 rad/s (the tip at 0.95 r, about
  // 3.97 m/s) needs a cue speed beyond 8 m/s; a little faster, the smaller offset brings it back
  // within (from about 4.10 m/s).
  ModelParameters far_tip = paper;
  far_tip.cue.max_tip_offset = 0.95;
  const double r = paper.ball.radius;
  const Eigen::Vector2d e(0.6, 0.8);
  struct Case {
    const ModelParameters& p;
    double k, wz;
    bool cue_speed_bounds_the_slowest;
  };
  for (const Case& c : {Case{paper, 1.0, 0.0, false}, Case{paper, -1.0, 40.0, false},
                        Case{paper, 0.0, -120.0, false}, Case{paper, 0.5, 300.0, false},
                        Case{far_tip, 0.0, 465.0, true}, Case{far_tip, 0.0, -465.0, true}}) {
    // A launch along e with R w = k v across the line and side spin wz.
    const auto stroke_for = [&](double speed) {
      const Eigen::Vector3d w(-c.k * speed / r * e.y(), c.k * speed / r * e.x(), c.wz);
      return StrokeFor(speed * e, w, c.p);
    };
    const LaunchSpeedRange range = LaunchSpeedsFor(c.k, c.wz, c.p);
    ASSERT_LT(range.min, range.max) << c.k << " " << c.wz;
    EXPECT_TRUE(stroke_for(range.max * (1 - 1e-9)).ok) << c.k << " " << c.wz;
    EXPECT_FALSE(stroke_for(range.max * (1 + 1e-6)).ok) << c.k << " " << c.wz;
    if (c.wz != 0.0) {
      EXPECT_TRUE(stroke_for(range.min * (1 + 1e-9)).ok) << c.k << " " << c.wz;
      const StrokeSolution slower = stroke_for(range.min * (1 - 1e-6));
      EXPECT_FALSE(slower.ok) << c.k << " " << c.wz;
      EXPECT_EQ(slower.reason.find("cue speed") != std::string::npos,
                c.cue_speed_bounds_the_slowest)
          << slower.reason;
    } else {
      EXPECT_EQ(range.min, 0.0);
    }
  }
  // More draw than half a radius of tip offset gives (R w / v = 5/2 q): no stroke at all.
  const LaunchSpeedRange none = LaunchSpeedsFor(-1.3, 0.0, paper);
  EXPECT_GT(none.min, none.max);
  // Side spin whose least cue speed is beyond the robot's.
  const LaunchSpeedRange too_much = LaunchSpeedsFor(0.0, 500.0, far_tip);
  EXPECT_GT(too_much.min, too_much.max);
}

}  // namespace
}  // namespace billiard::physics
