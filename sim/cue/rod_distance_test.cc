#include "sim/cue/rod_distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace billiard::cue {
namespace {

using Eigen::Vector3d;
constexpr double kNoEnd = std::numeric_limits<double>::infinity();

// A cue of `shape` with its tip at the origin, pointing back along +x.
PlacedCue AlongX(const CueShape& shape) {
  PlacedCue cue;
  cue.tip = Vector3d::Zero();
  cue.back = Vector3d::UnitX();
  cue.shape = shape;
  return cue;
}

// The least over `samples` + 1 evenly spaced points of the axis of `distance_from(s) - r(s)`:
// the rod as its definition says, sampled (an upper bound of the least, within a sample's step
// times the largest slope).
double Sampled(const PlacedCue& cue, const std::function<double(const Vector3d&)>& distance_from,
               int samples = 200000) {
  double least = kNoEnd;
  for (int i = 0; i <= samples; ++i) {
    const double s = cue.shape.length * i / samples;
    least = std::min(least, distance_from(cue.At(s)) - cue.shape.RadiusAt(s));
  }
  return least;
}

// A seeded cue anywhere, pointing anywhere, tapering as a real one (or much more).
PlacedCue RandomCue(std::mt19937_64* engine) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PlacedCue cue;
  cue.tip = Vector3d(unit(*engine), unit(*engine), unit(*engine));
  cue.back = Vector3d(unit(*engine) - 0.5, unit(*engine) - 0.5, unit(*engine) - 0.5).normalized();
  const double tip = 0.003 + 0.01 * unit(*engine);
  cue.shape = {0.3 + 1.2 * unit(*engine), tip, tip + 0.2 * unit(*engine)};
  return cue;
}

TEST(RodDistanceTest, SignedDistanceToABox) {
  const Box box{Vector3d(0, 0, -kNoEnd), Vector3d(1, 2, 0.04)};
  EXPECT_DOUBLE_EQ(SignedDistance({0.5, 1.0, 0.1}, box), 0.06);   // above the top
  EXPECT_DOUBLE_EQ(SignedDistance({1.3, 2.4, 0.04}, box), 0.5);   // off the top edge's corner
  EXPECT_DOUBLE_EQ(SignedDistance({0.5, 1.0, -5.0}, box), -0.5);  // inside: to the x = 0 face
  EXPECT_DOUBLE_EQ(SignedDistance({0.9, 1.0, 0.0}, box), -0.04);  // inside: to the top
  const Box wall{Vector3d(0, -kNoEnd, -kNoEnd), Vector3d(0, kNoEnd, 0.04)};  // of no width
  EXPECT_DOUBLE_EQ(SignedDistance({0.0, 3.0, 0.0}, wall), 0.0);
  EXPECT_DOUBLE_EQ(SignedDistance({-0.2, 3.0, 0.0}, wall), 0.2);
}

// Without taper the rod is a capsule: its distance is the segment's minus the radii.
TEST(RodDistanceTest, ACylinderIsACapsule) {
  const PlacedCue cue = AlongX({1.0, 0.01, 0.01});
  EXPECT_NEAR(DistanceToBall(cue, {0.4, 0.1, 0.0}, 0.03), 0.1 - 0.01 - 0.03, 1e-15);
  EXPECT_NEAR(DistanceToBall(cue, {-0.2, 0.0, 0.0}, 0.03), 0.2 - 0.01 - 0.03, 1e-15);
  EXPECT_NEAR(DistanceToBall(cue, {1.3, 0.4, 0.0}, 0.03), 0.5 - 0.01 - 0.03, 1e-15);
  const Box floor{Vector3d(-kNoEnd, -kNoEnd, -kNoEnd), Vector3d(kNoEnd, kNoEnd, -0.05)};
  EXPECT_NEAR(DistanceToBox(cue, floor), 0.04, 1e-12);
}

// The closed form's least distance to a ball against the rod sampled along its axis: never
// above the samples' least, and below it by no more than a step's worth.
TEST(RodDistanceTest, TheBallsClosedFormIsTheLeastAlongTheAxis) {
  std::mt19937_64 engine(47);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const PlacedCue cue = RandomCue(&engine);
    const Vector3d centre =
        cue.At(cue.shape.length * (1.4 * unit(engine) - 0.2)) +
        0.3 * Vector3d(unit(engine) - 0.5, unit(engine) - 0.5, unit(engine) - 0.5);
    const double radius = 0.03 * unit(engine);
    const double sampled =
        Sampled(cue, [&](const Vector3d& p) { return (p - centre).norm(); }) - radius;
    const double closed = DistanceToBall(cue, centre, radius);
    EXPECT_LE(closed, sampled + 1e-12);
    EXPECT_GE(closed, sampled - 2.0 * cue.shape.length / 200000);
  }
}

TEST(RodDistanceTest, TheBoxSearchIsTheLeastAlongTheAxis) {
  std::mt19937_64 engine(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const PlacedCue cue = RandomCue(&engine);
    const Vector3d corner(unit(engine), unit(engine), unit(engine));
    const Box box{corner, corner + Vector3d(unit(engine), 0.2 * unit(engine), 0.1 * unit(engine))};
    const double sampled = Sampled(cue, [&](const Vector3d& p) { return SignedDistance(p, box); });
    const double searched = DistanceToBox(cue, box);
    EXPECT_LE(searched, sampled + 1e-9);
    EXPECT_GE(searched, sampled - 2.0 * cue.shape.length / 200000);
  }
}

// A ball beside a tapered rod touches its side where the line from its centre meets the side
// at right angles, tilted from the perpendicular to the axis by the taper: the distance is
// rho sqrt(1 - k^2) - r(s_c) - R, not the naive rho - r(s_c) - R. A steep taper shows the
// difference (k = 0.5: a factor 0.866 on rho).
TEST(RodDistanceTest, ABallBesideTheSideMeetsItsNormal) {
  const PlacedCue cue = AlongX({1.0, 0.01, 0.51});
  const double rho = 0.6, s_c = 0.3, R = 0.02, k = 0.5;
  EXPECT_NEAR(DistanceToBall(cue, {s_c, 0.0, rho}, R),
              rho * std::sqrt(1 - k * k) - (0.01 + k * s_c) - R, 1e-15);
}

}  // namespace
}  // namespace billiard::cue
