// The cue's outline from above: the tapered rod's trapezoid about its axis, its width at each end
// the rod's there; and the label that names its elevation and what it clears.
#include "plot/cue_outline.h"

#include <gtest/gtest.h>

#include <cmath>

namespace billiard::plot {
namespace {

constexpr double kDegree = M_PI / 180.0;

// A cue along +x from its butt at the origin to its tip 0.4 m on.
CueOutline AlongX() {
  CueOutline cue;
  cue.butt = {0.0, 0.0};
  cue.tip = {0.4, 0.0};
  cue.tip_radius = 0.0065;
  cue.butt_radius = 0.0094;
  return cue;
}

TEST(CueOutline, TheCornersAreTheRodsWidthAcrossEachEnd) {
  const std::array<Eigen::Vector2d, 4> c = OutlineCorners(AlongX());
  EXPECT_TRUE(c[0].isApprox(Eigen::Vector2d(0.4, 0.0065)));
  EXPECT_TRUE(c[1].isApprox(Eigen::Vector2d(0.0, 0.0094)));
  EXPECT_TRUE(c[2].isApprox(Eigen::Vector2d(0.0, -0.0094)));
  EXPECT_TRUE(c[3].isApprox(Eigen::Vector2d(0.4, -0.0065)));
}

// Turned by any heading, the outline turns with it: the same widths across the axis.
TEST(CueOutline, TheOutlineTurnsWithTheHeading) {
  for (const double heading : {30 * kDegree, 135 * kDegree, 250 * kDegree}) {
    CueOutline cue = AlongX();
    const Eigen::Vector2d along(std::cos(heading), std::sin(heading));
    cue.tip = 0.4 * along;
    const std::array<Eigen::Vector2d, 4> c = OutlineCorners(cue);
    EXPECT_NEAR((c[0] - c[3]).norm(), 2 * 0.0065, 1e-12);
    EXPECT_NEAR((c[1] - c[2]).norm(), 2 * 0.0094, 1e-12);
    EXPECT_NEAR((c[0] - cue.tip).dot(along), 0.0, 1e-12);
  }
}

TEST(CueOutline, TheLabelNamesTheElevationAndWhatItClears) {
  CueOutline cue = AlongX();
  EXPECT_EQ(CueLabel(cue), "cue level");
  cue.elevation = 7.3 * kDegree;
  EXPECT_EQ(CueLabel(cue), "cue at 7.30 deg");
  cue.nearest = Eigen::Vector2d(0.2, 0.0);
  cue.nearest_what = "ball 3";
  cue.distance = 0.0042;
  EXPECT_EQ(CueLabel(cue), "cue at 7.30 deg, clears ball 3 by 4.2 mm");
  cue.nearest_what = "the lower rail";
  cue.distance = -0.0015;
  EXPECT_EQ(CueLabel(cue), "cue at 7.30 deg, meets the lower rail, 1.5 mm into it");
}

}  // namespace
}  // namespace billiard::plot
