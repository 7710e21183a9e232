// The hop against projectile motion and the impulse laws of a landing: angular momentum about the
// contact point kept (the bed's impulses act there), Coulomb's bound, the slip never reversed.
#include "sim/physics/hop.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "sim/physics/testing/test_support.h"

namespace billiard::physics {
namespace {

// The angular momentum about the ball's contact point with the cloth, per unit mass:
// I w / m + (r z) x v, with I = 2/5 m r^2.
Eigen::Vector3d AboutTheContact(const BallState& s, double r) {
  const Eigen::Vector3d w = s.segment<3>(kWx);
  const Eigen::Vector3d v(s[kVx], s[kVy], 0.0);
  return 0.4 * r * r * w + Eigen::Vector3d(0.0, 0.0, r).cross(v);
}

TEST(Hop, AFlightFromTheClothIsAProjectilesRiseAndFall) {
  const double g = 9.81, v = 0.2;
  const Flight up{0.0, v};
  EXPECT_NEAR(TimeToLand(up, g), 2.0 * v / g, 1e-15);
  EXPECT_NEAR(Apex(up, g), v * v / (2.0 * g), 1e-15);
  const Flight landing = FlightAfter(up, TimeToLand(up, g), g);
  EXPECT_NEAR(landing.height, 0.0, 1e-15);
  EXPECT_NEAR(landing.vertical_speed, -v, 1e-15);
  // Half way up the time that is left is the fall from the apex plus the rest of the rise.
  const Flight mid = FlightAfter(up, 0.25 * TimeToLand(up, g), g);
  EXPECT_NEAR(TimeToLand(mid, g), 0.75 * TimeToLand(up, g), 1e-15);
  EXPECT_TRUE(Airborne(up, g));
  EXPECT_FALSE(Airborne({}, g));
  EXPECT_FALSE(Airborne({0.0, std::sqrt(2.0 * g * kSettledHop) * 0.99}, g));
}

TEST(Hop, ARollingBallLandsWithoutFrictionAndBouncesLowerByTheRestitution) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  const BallState rolling = MakeBallState(0.3, 0.2, 1.0, 0.5, -0.5 / r, 1.0 / r, 4.0);
  const Landing l = LandOnBed(rolling, 0.3, p);
  EXPECT_EQ(l.state, rolling);
  EXPECT_NEAR(l.rebound.vertical_speed, kBedRestitution * 0.3, 1e-15);
  EXPECT_EQ(l.rebound.height, 0.0);
  // A landing too slow to rise kSettledHop again stays on the cloth.
  EXPECT_FALSE(Airborne(LandOnBed(rolling, 0.05, p).rebound, p.ball.gravity));
}

TEST(Hop, ASlidingLandingKeepsTheAngularMomentumAboutTheContactAndObeysCoulomb) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius, mu = p.contact.mu;
  // Side spin and a slip across the travel: a swerving ball.
  const BallState s = MakeBallState(0.0, 0.0, 2.0, 0.3, 10.0, -5.0, 30.0);
  const double landing = 0.2;
  const Landing l = LandOnBed(s, landing, p);
  EXPECT_LT((AboutTheContact(l.state, r) - AboutTheContact(s, r)).norm(), 1e-12);
  // The impulse is Coulomb's share of the normal one, against the slip.
  const Eigen::Vector2d dv = l.state.segment<2>(kVx) - s.segment<2>(kVx);
  EXPECT_NEAR(dv.norm(), mu * (1.0 + kBedRestitution) * landing, 1e-12);
  EXPECT_NEAR(dv.normalized().dot(-ClothSlip(s, r).normalized()), 1.0, 1e-12);
  EXPECT_EQ(l.state[kWz], s[kWz]);  // the bed's impulse has no moment about the vertical
  // The slip keeps its direction, shortened by 7/2 of the impulse.
  EXPECT_NEAR(ClothSlip(l.state, r).norm(), ClothSlip(s, r).norm() - 3.5 * dv.norm(), 1e-12);
}

TEST(Hop, AHardLandingStopsTheSlipAndNoMore) {
  const ModelParameters p = testing::PaperParameters();
  const double r = p.ball.radius;
  const BallState stun = MakeBallState(0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0);
  const Landing l = LandOnBed(stun, 10.0, p);
  EXPECT_NEAR(ClothSlip(l.state, r).norm(), 0.0, 1e-14);
  // Rolling without slip keeps the angular momentum about the contact: v = 5/7 v0.
  EXPECT_NEAR(l.state[kVx], 5.0 / 7.0 * 0.5, 1e-14);
}

TEST(Hop, TheCueDrivesTheBallDownByTheTangentOfItsElevation) {
  const ModelParameters p = testing::PaperParameters();
  const CueStroke level{2.0, 0.4, 0.0, 0.0, 0.0};
  EXPECT_EQ(LaunchUpSpeed(level, StrikeBall(level, {0.5, 0.5}, p)), 0.0);
  const double elevation = 10.0 * M_PI / 180.0;
  const CueStroke raised{2.0, 0.4, 0.0, 0.0, elevation};
  const BallState launch = StrikeBall(raised, {0.5, 0.5}, p);
  // A centre hit: the impulse, and so the launch, is along the cue's axis.
  EXPECT_NEAR(LaunchUpSpeed(raised, launch),
              kBedRestitution * launch.segment<2>(kVx).norm() * std::tan(elevation), 1e-12);
}

}  // namespace
}  // namespace billiard::physics
