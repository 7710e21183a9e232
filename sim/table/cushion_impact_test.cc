#include "sim/table/cushion_impact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

namespace billiard::table {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// Mathavan et al. 2010's snooker ball (their section on numerical results): R = 26.25 mm,
// M = 0.1406 kg.
const physics::BallParameters kSnookerBall{0.02625, 0.1406, 9.81};
const physics::BallParameters kPoolBall{0.05715 / 2.0, 0.170097, 9.81};
const physics::BallParameters kCaromBall{0.0615 / 2.0, 0.210, 9.81};

// A ball arriving with speed V at `incidence` from the cushion line (0 grazing, 90 degrees
// head-on), with top spin omega_T about the horizontal axis across its path (omega_T = V / R
// rolls) and side spin omega_S about z: Mathavan 2010's initial conditions.
ImpactVelocities Arriving(double speed, double incidence, double top_spin, double side_spin) {
  const double c = std::cos(incidence), s = std::sin(incidence);
  return {Eigen::Vector3d(speed * c, speed * s, 0.0),
          Eigen::Vector3d(-top_spin * s, top_spin * c, side_spin)};
}

double ReboundSpeed(const ImpactVelocities& after) { return after.v.head<2>().norm(); }

// From the cushion line, as the incidence.
double ReboundAngle(const ImpactVelocities& after) { return std::atan2(-after.v.y(), after.v.x()); }

double KineticEnergy(const ImpactVelocities& s, const physics::BallParameters& ball) {
  const double inertia = 0.4 * ball.mass * ball.radius * ball.radius;
  return 0.5 * ball.mass * s.v.squaredNorm() + 0.5 * inertia * s.w.squaredNorm();
}

struct NoseAngle {
  double sin_theta, cos_theta;
};
NoseAngle NoseAngleOf(const CushionParameters& cushion, const physics::BallParameters& ball) {
  const double s = (cushion.height - ball.radius) / ball.radius;
  return {s, std::sqrt(1.0 - s * s)};
}

// Mathavan et al. 2010, figure 9: rebound speed and angle against incidence for V0 = 1 m/s, top
// spin omega_T = k V0 / R, no side spin, with their parameters (kSnookerCushion, kSnookerBall).
// The paper's own plot could not be read here; the values are read off the figure as re-plotted,
// from the paper's equations and parameters, by the tailuge/billiards project
// (github.com/tailuge/billiards, dist/images/mathavangraphs.jpg, "Figure.9"), to its reading
// accuracy: 0.01 m/s in speed, 1.5 degrees in angle.
struct Figure9Reading {
  double k, incidence_deg, speed, angle_deg;
};
constexpr Figure9Reading kFigure9[] = {
    {-1.0, 19.0, 0.852, 21.5}, {-1.0, 46.0, 0.801, 56.0}, {-1.0, 82.0, 0.860, 87.0},
    {0.0, 19.0, 0.848, 21.5},  {0.0, 46.0, 0.757, 57.5},  {0.0, 82.0, 0.828, 85.5},
    {1.0, 19.0, 0.898, 20.5},  {1.0, 46.0, 0.847, 54.0},  {1.0, 82.0, 0.901, 84.5},
    {2.0, 19.0, 0.948, 19.5},  {2.0, 46.0, 0.913, 49.5},  {2.0, 82.0, 0.974, 83.5},
};
constexpr double kFigureSpeedReading = 0.01;           // m/s
constexpr double kFigureAngleReading = 1.5 * kDegree;  // rad

TEST(CushionImpactTest, MathavanReproducesFigure9) {
  for (const Figure9Reading& point : kFigure9) {
    const double top_spin = point.k * 1.0 / kSnookerBall.radius;
    const ImpactVelocities after = ResolveCushionImpact(
        CushionModel::kMathavan2010, Arriving(1.0, point.incidence_deg * kDegree, top_spin, 0.0),
        kSnookerBall, kSnookerCushion);
    SCOPED_TRACE("k = " + std::to_string(point.k) +
                 ", incidence = " + std::to_string(point.incidence_deg));
    EXPECT_NEAR(ReboundSpeed(after), point.speed, kFigureSpeedReading);
    EXPECT_NEAR(ReboundAngle(after), point.angle_deg * kDegree, kFigureAngleReading);
  }
}

// Mathavan et al. 2010, figure 12: the slip at the cushion (s, phi) and at the cloth (s', phi')
// through the impact of V0 = 2 m/s at 45 degrees with omega_S = 2 V0 / R, omega_T = 1.5 V0 / R.
// Their values at the end of the impact, read (0.05 m/s, 0.05 rad) off the same re-plot
// (tailuge/billiards, "Figure.12"): s = 0.58, phi = 3.68, s' = 2.25, phi' = 4.52. Angles as
// Mathavan's: phi from x towards y' = (0, -sin(theta), cos(theta)), both in [0, 2 pi).
TEST(CushionImpactTest, MathavanReproducesFigure12FinalSlips) {
  const double v0 = 2.0, r = kSnookerBall.radius;
  const ImpactVelocities after = ResolveCushionImpact(
      CushionModel::kMathavan2010, Arriving(v0, 45.0 * kDegree, 1.5 * v0 / r, 2.0 * v0 / r),
      kSnookerBall, kSnookerCushion);
  const NoseAngle nose = NoseAngleOf(kSnookerCushion, kSnookerBall);
  const double nose_x =
      after.v.x() + after.w.y() * r * nose.sin_theta - after.w.z() * r * nose.cos_theta;
  const double nose_y = -after.v.y() * nose.sin_theta + after.w.x() * r;
  const double cloth_x = after.v.x() - after.w.y() * r;
  const double cloth_y = after.v.y() + after.w.x() * r;
  const auto angle = [](double y, double x) {
    const double a = std::atan2(y, x);
    return a < 0.0 ? a + 2.0 * kPi : a;
  };
  EXPECT_NEAR(std::hypot(nose_x, nose_y), 0.58, 0.05);
  EXPECT_NEAR(angle(nose_y, nose_x), 3.68, 0.05);
  EXPECT_NEAR(std::hypot(cloth_x, cloth_y), 2.25, 0.05);
  EXPECT_NEAR(angle(cloth_y, cloth_x), 4.52, 0.05);
}

// Without friction the impulse at I is along n; the cloth takes its vertical part, so v.y falls
// linearly in P and the work-based restitution gives back exactly v.y' = -e_e v.y; nothing else
// changes.
TEST(CushionImpactTest, MathavanWithoutFrictionReboundsWithRestitution) {
  CushionParameters frictionless = kSnookerCushion;
  frictionless.friction = 0.0;
  frictionless.cloth_friction = 0.0;
  const ImpactVelocities before = Arriving(1.3, 35.0 * kDegree, 40.0, -25.0);
  const ImpactVelocities after =
      ResolveCushionImpact(CushionModel::kMathavan2010, before, kSnookerBall, frictionless);
  EXPECT_NEAR(after.v.x(), before.v.x(), 1e-12);
  EXPECT_NEAR(after.v.y(), -frictionless.restitution * before.v.y(), 1e-12);
  EXPECT_EQ(after.v.z(), 0.0);
  EXPECT_NEAR((after.w - before.w).norm(), 0.0, 1e-9);
}

// Head-on with strong overspin (R w_x = -5 v.y, against rolling's -1) the slip at I and at C
// points the same way (-y', -y) throughout, so every rate is constant: v.y is linear in P, the
// ratio is exactly e_e and the spin change is that of the total impulse M v.y (1 + e_e) / K,
//   K = cos(theta) + mu_w sin(theta) - mu_s N,   N = sin(theta) - mu_w cos(theta),
//   (2/5) M R dw_x/dP = mu_w + mu_s N.
TEST(CushionImpactTest, MathavanHeadOnWithOverspinMatchesConstantSlipSolution) {
  const CushionParameters cushion = kSnookerCushion;
  const double vy = 1.1, r = kSnookerBall.radius, m = kSnookerBall.mass;
  const ImpactVelocities before{Eigen::Vector3d(0.0, vy, 0.0),
                                Eigen::Vector3d(-5.0 * vy / r, 0.0, 0.0)};
  const ImpactVelocities after =
      ResolveCushionImpact(CushionModel::kMathavan2010, before, kSnookerBall, cushion);

  const NoseAngle nose = NoseAngleOf(cushion, kSnookerBall);
  const double mu_w = cushion.friction, mu_s = cushion.cloth_friction, e = cushion.restitution;
  const double cloth_normal = nose.sin_theta - mu_w * nose.cos_theta;
  const double k = nose.cos_theta + mu_w * nose.sin_theta - mu_s * cloth_normal;
  const double total_impulse = m * vy * (1.0 + e) / k;
  const double spin_change = (mu_w + mu_s * cloth_normal) * r * total_impulse / (0.4 * m * r * r);

  EXPECT_NEAR(after.v.y(), -e * vy, 1e-12);
  EXPECT_NEAR(after.w.x(), before.w.x() + spin_change, 1e-9);
  EXPECT_EQ(after.v.x(), 0.0);
  EXPECT_EQ(after.w.y(), 0.0);
  EXPECT_EQ(after.w.z(), 0.0);
}

// Head-on without spin nothing acts along x, so the ball comes straight back without side spin.
// Han: the slip at I, -sin(theta) v.y down the nose, stops within the impulse (grip, as
// 2/7 M sin(theta) v.y < mu_w P_n here), and the friction impulse up the nose has a part
// -sin(theta) along y: v.y'/v.y = (1 + e_e) cos^2(theta) - 1 + 2/7 sin^2(theta) exactly.
// Mathavan: the friction at I and C spins the ball up, so the ratio is below e_e; figure 9's
// k = 0 curve (read as above) is at 0.828 at 82 degrees, the nearest it comes to head-on.
TEST(CushionImpactTest, HeadOnWithoutSpinReboundsNormally) {
  const ImpactVelocities before{Eigen::Vector3d(0.0, 1.5, 0.0), Eigen::Vector3d::Zero()};
  const CushionParameters cushion = kSnookerCushion;
  const double e = cushion.restitution;
  for (CushionModel model : {CushionModel::kMathavan2010, CushionModel::kHan2005}) {
    const ImpactVelocities after = ResolveCushionImpact(model, before, kSnookerBall, cushion);
    EXPECT_EQ(after.v.x(), 0.0);
    EXPECT_EQ(after.w.y(), 0.0);
    EXPECT_EQ(after.w.z(), 0.0);
    const double ratio = -after.v.y() / before.v.y();
    if (model == CushionModel::kMathavan2010) {
      EXPECT_LT(ratio, e);
      EXPECT_NEAR(ratio, 0.828, 2.0 * kFigureSpeedReading);
    } else {
      const NoseAngle nose = NoseAngleOf(cushion, kSnookerBall);
      EXPECT_NEAR(ratio,
                  (1.0 + e) * nose.cos_theta * nose.cos_theta - 1.0 +
                      2.0 / 7.0 * nose.sin_theta * nose.sin_theta,
                  1e-12);
    }
  }
}

// The cushion frame's mirror x -> -x maps v to (-vx, vy, vz) and the axial w to (wx, -wy, -wz);
// the impact must commute with it.
ImpactVelocities Mirrored(const ImpactVelocities& s) {
  return {Eigen::Vector3d(-s.v.x(), s.v.y(), s.v.z()),
          Eigen::Vector3d(s.w.x(), -s.w.y(), -s.w.z())};
}

TEST(CushionImpactTest, MirrorSymmetric) {
  std::mt19937 rng(20100901);
  std::uniform_real_distribution<double> incidence(1.0 * kDegree, 89.0 * kDegree);
  std::uniform_real_distribution<double> spin_ratio(-3.0, 3.0);
  for (CushionModel model : {CushionModel::kMathavan2010, CushionModel::kHan2005}) {
    for (int trial = 0; trial < 50; ++trial) {
      const double speed = 2.0, r = kPoolBall.radius;
      const ImpactVelocities before =
          Arriving(speed, incidence(rng), spin_ratio(rng) * speed / r, spin_ratio(rng) * speed / r);
      const ImpactVelocities after = ResolveCushionImpact(model, before, kPoolBall, kPoolCushion);
      const ImpactVelocities mirrored_after =
          ResolveCushionImpact(model, Mirrored(before), kPoolBall, kPoolCushion);
      EXPECT_NEAR((mirrored_after.v - Mirrored(after).v).norm(), 0.0, 1e-12);
      EXPECT_NEAR((mirrored_after.w - Mirrored(after).w).norm(), 0.0, 1e-9);
    }
  }
}

// Neither model has a velocity scale: scaling every input velocity scales the output.
TEST(CushionImpactTest, HomogeneousInTheVelocities) {
  const double r = kCaromBall.radius;
  const ImpactVelocities before = Arriving(0.7, 28.0 * kDegree, 1.3 * 0.7 / r, -0.8 * 0.7 / r);
  const ImpactVelocities scaled{4.0 * before.v, 4.0 * before.w};
  for (CushionModel model : {CushionModel::kMathavan2010, CushionModel::kHan2005}) {
    const ImpactVelocities after = ResolveCushionImpact(model, before, kCaromBall, kCaromCushion);
    const ImpactVelocities after_scaled =
        ResolveCushionImpact(model, scaled, kCaromBall, kCaromCushion);
    EXPECT_NEAR((after_scaled.v - 4.0 * after.v).norm(), 0.0, 1e-12);
    EXPECT_NEAR((after_scaled.w - 4.0 * after.w).norm(), 0.0, 1e-9);
  }
}

// Friction only dissipates and the restitution gives back at most what compression took: the
// kinetic energy (with the ball's spin) never rises, for random speeds 0.1-8 m/s, incidences,
// spins up to 3 v / R on every axis, and random parameters as well as the recommended sets.
TEST(CushionImpactTest, EnergyNeverRises) {
  std::mt19937 rng(1863);
  std::uniform_real_distribution<double> speed(0.1, 8.0);
  std::uniform_real_distribution<double> incidence(0.5 * kDegree, 90.0 * kDegree);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  const struct {
    physics::BallParameters ball;
    CushionParameters cushion;
  } kSets[] = {
      {kPoolBall, kPoolCushion}, {kSnookerBall, kSnookerCushion}, {kCaromBall, kCaromCushion}};
  for (CushionModel model : {CushionModel::kMathavan2010, CushionModel::kHan2005}) {
    for (int trial = 0; trial < 300; ++trial) {
      const auto& set = kSets[trial % 3];
      CushionParameters cushion = set.cushion;
      if (trial % 2 == 1) {  // random parameters in the physical range
        cushion.height = set.ball.radius * (1.0 + 0.6 * fraction(rng));
        cushion.restitution = fraction(rng);
        cushion.friction = 0.3 * fraction(rng);
        cushion.cloth_friction = 0.3 * fraction(rng);
      }
      const double v = speed(rng), r = set.ball.radius;
      const double a = incidence(rng);
      const ImpactVelocities before{Eigen::Vector3d(v * std::cos(a), v * std::sin(a), 0.0),
                                    Eigen::Vector3d(unit(rng), unit(rng), unit(rng)) * 3.0 * v / r};
      const ImpactVelocities after = ResolveCushionImpact(model, before, set.ball, cushion);
      const double energy_before = KineticEnergy(before, set.ball);
      EXPECT_LE(KineticEnergy(after, set.ball), energy_before * (1.0 + 1e-12)) << "trial " << trial;
      EXPECT_EQ(after.v.z(), 0.0);
      // Han's free sphere can go on into the cushion with a high nose and a low e_e (header).
      if (model == CushionModel::kMathavan2010 || trial % 2 == 0) {
        EXPECT_LE(after.v.y(), 0.0) << "trial " << trial << ": the ball must leave the cushion";
      }
    }
  }
}

// Han 2005 with mu_w = 0: the impulse is along n, through the centre: v.x and the spin keep,
// and v.y' = (1 - (1 + e_e) cos^2(theta)) v.y; with the nose at the centre's height, -e_e v.y.
TEST(CushionImpactTest, HanWithoutFrictionKeepsTangentialVelocityAndSpin) {
  CushionParameters cushion = kCaromCushion;
  cushion.friction = 0.0;
  const ImpactVelocities before = Arriving(1.7, 40.0 * kDegree, 50.0, 30.0);
  const NoseAngle nose = NoseAngleOf(cushion, kCaromBall);
  ImpactVelocities after =
      ResolveCushionImpact(CushionModel::kHan2005, before, kCaromBall, cushion);
  EXPECT_NEAR(after.v.x(), before.v.x(), 1e-12);
  EXPECT_NEAR((after.w - before.w).norm(), 0.0, 1e-12);
  EXPECT_NEAR(after.v.y(),
              (1.0 - (1.0 + cushion.restitution) * nose.cos_theta * nose.cos_theta) * before.v.y(),
              1e-12);

  cushion.height = kCaromBall.radius;
  after = ResolveCushionImpact(CushionModel::kHan2005, before, kCaromBall, cushion);
  EXPECT_NEAR(after.v.y(), -cushion.restitution * before.v.y(), 1e-12);
}

// Han 2005 with the nose at the centre's height (theta = 0, no vertical impulse to drop), so its
// two friction cases are exact rigid-body results:
//   sliding throughout (small mu_w): the friction impulse is mu_w P_n = mu_w (1 + e_e) M v.y along
//   the slip, here along x, so v.x drops by mu_w (1 + e_e) v.y and w.z gains
//   5 mu_w (1 + e_e) v.y / (2 R);
//   gripping (large mu_w): the slip at I, (v.x - R w.z, R w.x), ends at zero.
TEST(CushionImpactTest, HanSlidesOrGripsAtTheNose) {
  CushionParameters cushion = kCaromCushion;
  cushion.height = kCaromBall.radius;
  const double r = kCaromBall.radius, e = cushion.restitution;
  const ImpactVelocities before{Eigen::Vector3d(1.0, 1.0, 0.0), Eigen::Vector3d::Zero()};

  cushion.friction = 0.1;
  ImpactVelocities after =
      ResolveCushionImpact(CushionModel::kHan2005, before, kCaromBall, cushion);
  EXPECT_NEAR(after.v.x(), 1.0 - cushion.friction * (1.0 + e), 1e-12);
  EXPECT_NEAR(after.w.z(), 2.5 * cushion.friction * (1.0 + e) / r, 1e-9);
  EXPECT_NEAR(after.v.y(), -e, 1e-12);

  cushion.friction = 1.0;
  after = ResolveCushionImpact(CushionModel::kHan2005, before, kCaromBall, cushion);
  EXPECT_NEAR(after.v.x() - r * after.w.z(), 0.0, 1e-12);
  EXPECT_NEAR(r * after.w.x(), 0.0, 1e-12);
  // Gripping, the ball keeps 5/7 of its tangential speed (angular momentum about I).
  EXPECT_NEAR(after.v.x(), 5.0 / 7.0, 1e-12);
}

void ExpectRefused(CushionModel model, const ImpactVelocities& before,
                   const physics::BallParameters& ball, const CushionParameters& cushion,
                   const std::string& reason_part, double steps = kMathavanSteps) {
  try {
    ResolveCushionImpact(model, before, ball, cushion, steps);
    ADD_FAILURE() << "accepted; expected a refusal mentioning '" << reason_part << "'";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(reason_part), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  }
}

// Fewer steps (a search's, which the default then checks) converge on the same rebound: over
// random incidences and spins up to 3 v / R, 50 and 250 steps per approach momentum against 5000.
TEST(CushionImpactTest, MathavanFewerStepsConverge) {
  std::mt19937 random(2010);
  std::uniform_real_distribution<double> incidence(5.0 * kDegree, 90.0 * kDegree), spin(-3.0, 3.0);
  double worst_coarse = 0.0, worst_default = 0.0;  // rebound angle error [rad]
  double worst_speed = 0.0;                        // rebound speed error, 50 steps [m/s]
  for (int i = 0; i < 200; ++i) {
    const double r = kPoolBall.radius;
    const ImpactVelocities before = Arriving(1.0, incidence(random), spin(random) / r, spin(random) / r);
    const auto at = [&](double steps) {
      return ResolveCushionImpact(CushionModel::kMathavan2010, before, kPoolBall, kPoolCushion, steps);
    };
    const ImpactVelocities fine = at(5000.0), coarse = at(50.0), standard = at(kMathavanSteps);
    worst_coarse = std::max(worst_coarse, std::abs(ReboundAngle(coarse) - ReboundAngle(fine)));
    worst_default = std::max(worst_default, std::abs(ReboundAngle(standard) - ReboundAngle(fine)));
    worst_speed = std::max(worst_speed, std::abs(ReboundSpeed(coarse) - ReboundSpeed(fine)));
  }
  std::printf("rebound angle error: 50 steps %.4f deg, %g steps %.4f deg; speed, 50 steps %.2e\n",
              worst_coarse / kDegree, kMathavanSteps, worst_default / kDegree, worst_speed);
  EXPECT_LT(worst_default, worst_coarse);
  EXPECT_LT(worst_coarse, 0.1 * kDegree);
  EXPECT_LT(worst_speed, 2e-3);
}

TEST(CushionImpactTest, RefusesBadInput) {
  const ImpactVelocities good = Arriving(1.0, 30.0 * kDegree, 0.0, 0.0);
  ImpactVelocities leaving = good;
  leaving.v.y() = -0.1;
  ImpactVelocities touching = good;
  touching.v.y() = 0.0;
  ImpactVelocities not_finite = good;
  not_finite.w.z() = std::nan("");
  for (CushionModel model : {CushionModel::kMathavan2010, CushionModel::kHan2005}) {
    ExpectRefused(model, leaving, kPoolBall, kPoolCushion, "approach");
    ExpectRefused(model, touching, kPoolBall, kPoolCushion, "approach");
    ExpectRefused(model, not_finite, kPoolBall, kPoolCushion, "finite");
    physics::BallParameters massless = kPoolBall;
    massless.mass = 0.0;
    ExpectRefused(model, good, massless, kPoolCushion, "mass");
    physics::BallParameters pointlike = kPoolBall;
    pointlike.radius = 0.0;
    ExpectRefused(model, good, pointlike, kPoolCushion, "radius");
    CushionParameters low = kPoolCushion;
    low.height = 0.9 * kPoolBall.radius;
    ExpectRefused(model, good, kPoolBall, low, "height");
    CushionParameters high = kPoolCushion;
    high.height = 2.0 * kPoolBall.radius;
    ExpectRefused(model, good, kPoolBall, high, "height");
    CushionParameters bouncy = kPoolCushion;
    bouncy.restitution = 1.01;
    ExpectRefused(model, good, kPoolBall, bouncy, "restitution");
    CushionParameters negative = kPoolCushion;
    negative.friction = -0.1;
    ExpectRefused(model, good, kPoolBall, negative, "cushion friction");
    negative = kPoolCushion;
    negative.cloth_friction = -0.1;
    ExpectRefused(model, good, kPoolBall, negative, "cloth friction");
  }
  // Jamming: cos(theta) <= mu_w sin(theta) + mu_s (sin(theta) + mu_w cos(theta)).
  CushionParameters sticky = kPoolCushion;
  sticky.friction = 1.0;
  sticky.cloth_friction = 1.0;
  ExpectRefused(CushionModel::kMathavan2010, good, kPoolBall, sticky, "friction too high");
  for (double steps : {0.5, std::nan("")}) {
    ExpectRefused(CushionModel::kMathavan2010, good, kPoolBall, kPoolCushion, "steps", steps);
  }
}

}  // namespace
}  // namespace billiard::table
