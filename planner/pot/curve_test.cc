// A curve around a ball, end to end: planned within the hop limit (cue::TableMaxHop) at a low
// elevation, and played on the table's own replay (`simulate --scene`'s motion), where the cue
// ball bends around the ball a straight stroke cannot pass and pots; a curve no hop-free stroke
// bends enough stays refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "planner/pot/pot_geometry.h"
#include "planner/pot/pot_planner.h"
#include "planner/pot/testing/pot_fixture.h"
#include "sim/cue/stroke_limits.h"
#include "sim/params/robots.h"

namespace billiard::pot {
namespace {

using table::SceneBall;

class CurveTest : public testing::PotFixture {
 protected:
  // docs/pictures/curve_scene.json: ball 2 stands 5.1 cm off the cue ball's line to ball 1's
  // ghost ball for the upper right corner, 6 mm less than the two radii a straight stroke needs to
  // pass it; balls 3 and 4 stand away from the routes (without ball 3 the curve's cue ball
  // follows into the lower right corner).
  const std::vector<SceneBall> balls_ = {table::AtRest(0, 0.6, 0.7), table::AtRest(1, 1.6, 0.7),
                                         table::AtRest(2, 1.1, 0.735), table::AtRest(3, 2.1, 0.35),
                                         table::AtRest(4, 0.9, 1.05)};
  const Eigen::Vector2d cue_{0.6, 0.7}, blocker_{1.1, 0.735};
};

// The distance from `p` to the segment from `a` to `b`.
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

TEST_F(CurveTest, ACurveAroundABallIsPlannedWithinTheHopLimitAndBendsAroundItToPot) {
  const PotPlan plan = PlanPot(table_, params_, balls_, {1, "upper_right", ShotKind::kCurve, {}});
  ExpectLegalPot(balls_, plan);
  EXPECT_EQ(plan.kind, ShotKind::kCurve);
  // Within the hop limit and the gantry's (the default robot's) ranges.
  EXPECT_LE(cue::HopHeight(plan.stroke, cue_, params_), cue::TableMaxHop(params_) * (1 + 1e-9));
  EXPECT_EQ(cue::OutsideRanges(params::LoadRobot("gantry"), plan.stroke, params_.ball.radius), "");
  EXPECT_GT(plan.stroke.elevation, 0.0);
  EXPECT_NE(plan.stroke.tip_side, 0.0);
  // Played on the replay: the cue ball meets ball 1 first from where the straight line back to
  // its start passes through ball 2 (closer than two radii): its path bent around ball 2.
  const Outcome played = SimulatePlan(balls_, plan);
  ASSERT_EQ(played.first_contact, 1);
  EXPECT_LT(DistanceToSegment(blocker_, cue_, played.cue_at_contact), 2.0 * params_.ball.radius);
}

// The straight strokes the curve replaces: every level heading across ball 1 (from one grazing
// side to the other, 0.02 degrees apart, finer than a pot's heading window of a few tenths), with
// the largest side offset either way (its throw turns ball 1) and none. Those that meet ball 1
// first do not pot it; some do meet it first (the scan reaches past ball 2).
TEST_F(CurveTest, NoStraightStrokePotsPastTheBall) {
  const double r = params_.ball.radius;
  const Eigen::Vector2d k = balls_[1].state.head<2>();
  const double centre = Angle(k - cue_), half = std::asin(2.0 * r / (k - cue_).norm());
  constexpr double kStep = 0.02 * kDegree, kSpeed = 2.0;
  int met_first = 0;
  for (double side : {-1.0, 0.0, 1.0}) {
    for (double heading = centre - half; heading <= centre + half; heading += kStep) {
      const physics::CueStroke stroke{kSpeed, heading, side * params_.cue.max_tip_offset * r, 0.0, 0.0};
      const Outcome o = SimulateStroke(balls_, stroke, 1, "upper_right");
      if (o.first_contact != 1) continue;
      ++met_first;
      EXPECT_FALSE(o.potted) << "heading " << heading / kDegree << " deg, side " << side;
    }
  }
  EXPECT_GT(met_first, 0);
}

// Ball 2 squarely across the cue ball's line (docs/pictures/pot_scene.json): no hop-free curve
// bends a centimetre and more around it; refused, with the reason.
TEST_F(CurveTest, ACurveNoHopFreeStrokeBendsEnoughIsRefused) {
  const std::vector<SceneBall> balls = {table::AtRest(0, 0.55, 0.45), table::AtRest(1, 1.55, 0.8),
                                        table::AtRest(2, 1.05, 0.64)};
  const PotPlan plan = PlanPot(table_, params_, balls, {1, "upper_right", ShotKind::kCurve, {}});
  EXPECT_EQ(plan.status, PotStatus::kBlocked) << plan.reason;
  EXPECT_NE(plan.reason.find("curve: the cue ball meets ball 2 before ball 1"), std::string::npos) << plan.reason;
}

}  // namespace
}  // namespace billiard::pot
