#include "sim/cue/placed_cue.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/params/parameter_sets.h"

namespace billiard::cue {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kR = 0.028575;
const CueShape kCue{1.47, 0.0065, 0.0155};

// Seeded strokes over every heading, elevations in [0, 80) degrees, tip offsets within 0.9 r.
physics::CueStroke RandomStroke(std::mt19937_64* engine) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double offset = 0.9 * kR * std::sqrt(unit(*engine)), angle = 2 * M_PI * unit(*engine);
  return {2.0, 2 * M_PI * unit(*engine), offset * std::cos(angle), offset * std::sin(angle),
          80 * kDegree * unit(*engine)};
}

TEST(PlacedCueTest, ALevelCentreStrokeIsHeldAtTheBallsBack) {
  const PlacedCue cue = PlaceCue({1.0, 0.5}, kR, {2.0, 0.0, 0.0, 0.0, 0.0}, kCue);
  EXPECT_TRUE(cue.tip.isApprox(Eigen::Vector3d(1.0 - kR, 0.5, kR), 1e-15));
  EXPECT_TRUE(cue.back.isApprox(Eigen::Vector3d(-1, 0, 0), 1e-15));
  EXPECT_TRUE(cue.At(kCue.length).isApprox(Eigen::Vector3d(1.0 - kR - 1.47, 0.5, kR), 1e-15));
}

// Every tip on the ball's surface, every axis along the heading raised by the elevation, and
// the axis passing the centre at the tip offset's distance (b is across the axis).
TEST(PlacedCueTest, TipOnTheBallAxisAlongTheStrokeOffsetAcrossIt) {
  std::mt19937_64 engine(47);
  const Eigen::Vector3d centre(1.2, 0.6, kR);
  for (int i = 0; i < 500; ++i) {
    const physics::CueStroke s = RandomStroke(&engine);
    const PlacedCue cue = PlaceCue(centre.head<2>(), kR, s, kCue);
    EXPECT_NEAR((cue.tip - centre).norm(), kR, 1e-15);
    const Eigen::Vector3d back(-std::cos(s.heading) * std::cos(s.elevation),
                               -std::sin(s.heading) * std::cos(s.elevation), std::sin(s.elevation));
    EXPECT_TRUE(cue.back.isApprox(back, 1e-14));
    const Eigen::Vector3d to_centre = centre - cue.tip;
    EXPECT_NEAR((to_centre - to_centre.dot(cue.back) * cue.back).norm(),
                std::hypot(s.tip_side, s.tip_height), 1e-15);
    EXPECT_LT(to_centre.dot(cue.back), 0.0) << "the cue lies behind the ball, not through it";
  }
}

// Right english puts the tip right of the heading; follow puts it above the centre.
TEST(PlacedCueTest, OffsetsRightAndUp) {
  const Eigen::Vector2d centre(1.0, 0.5);
  const double heading = 30 * kDegree;
  const Eigen::Vector3d right(std::sin(heading), -std::cos(heading), 0.0);
  const PlacedCue english = PlaceCue(centre, kR, {2.0, heading, 0.01, 0.0, 0.0}, kCue);
  EXPECT_NEAR((english.tip - Eigen::Vector3d(1.0, 0.5, kR)).dot(right), 0.01, 1e-15);
  const PlacedCue follow = PlaceCue(centre, kR, {2.0, heading, 0.0, 0.01, 0.0}, kCue);
  EXPECT_NEAR(follow.tip.z(), kR + 0.01, 1e-15);
}

// The placement is the strike's: the spin StrikeBall gives is P x J / I, so it is
// perpendicular to the contact point P, and without a side offset (J along the cue's axis) it
// lies along P x c.
TEST(PlacedCueTest, TheContactIsTheStrikesOwn) {
  const physics::ModelParameters p = params::LoadParameters("pool");
  const double r = p.ball.radius;
  std::mt19937_64 engine(3);
  for (int i = 0; i < 200; ++i) {
    physics::CueStroke s = RandomStroke(&engine);
    s.tip_side *= 0.5, s.tip_height *= 0.5;  // within the strike's offsets
    if (i % 2 == 0) s.tip_side = 0.0;
    const Eigen::Vector3d contact =
        PlaceCue({0.0, 0.0}, r, s, kCue).tip - Eigen::Vector3d(0.0, 0.0, r);
    const physics::BallState launch = physics::StrikeBall(s, {0.0, 0.0}, p);
    const Eigen::Vector3d spin(launch[4], launch[5], launch[6]);
    EXPECT_NEAR(contact.normalized().dot(spin.normalized()), 0.0, 1e-12);
    if (s.tip_side == 0.0 && s.tip_height != 0.0) {
      const Eigen::Vector3d along = contact.cross(-PlaceCue({0, 0}, r, s, kCue).back);
      EXPECT_NEAR(along.normalized().dot(spin.normalized()), 1.0, 1e-12);
    }
  }
}

TEST(PlacedCueTest, RefusesATipOffTheBall) {
  EXPECT_THROW(PlaceCue({0, 0}, kR, {2.0, 0.0, kR, 0.0, 0.0}, kCue), std::invalid_argument);
  EXPECT_THROW(PlaceCue({0, 0}, kR, {2.0, NAN, 0.0, 0.0, 0.0}, kCue), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::cue
