#include "sim/cue/stroke_limits.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/table/table_geometry.h"

namespace billiard::cue {
namespace {

constexpr double kDegree = M_PI / 180.0;

class StrokeLimitsTest : public testing::Test {
 protected:
  physics::ModelParameters params_ = params::LoadParameters("pool");
};

// A centre hit's impulse along the cue (Alciatore 2004, TP A.30 with no offset):
// J = (1 + e) M m V / (m + M); its vertical part J sin(elevation) / m drives the ball down, and
// the bed returns kBedRestitution of it: the hop is (e_t J sin(elevation) / m)^2 / (2 g).
TEST_F(StrokeLimitsTest, TheHopIsTheBedsReturnOfTheCuesDownwardImpulse) {
  const physics::CueStroke level{2.0, 0.3, 0.0, 0.0, 0.0};
  EXPECT_EQ(HopHeight(level, {1.0, 0.6}, params_), 0.0);
  const double elevation = 12.0 * kDegree, V = 2.0;
  const double m = params_.ball.mass, M = params_.cue.mass, e = params_.cue.tip_restitution;
  const double j = (1 + e) * M * m * V / (m + M);
  const double up = physics::kBedRestitution * j * std::sin(elevation) / m;
  EXPECT_NEAR(HopHeight({V, 0.3, 0.0, 0.0, elevation}, {1.0, 0.6}, params_), up * up / (2 * params_.ball.gravity),
              1e-12);
}

// The hop grows with the square of the cue speed: the fastest stroke within a hop limit hops
// exactly the limit (the table's, a tenth of a radius, or the 1 mm of a motion on the cloth), and a
// level cue has no such limit.
TEST_F(StrokeLimitsTest, TheFastestStrokeWithinAHopLimitHopsTheLimit) {
  EXPECT_DOUBLE_EQ(TableMaxHop(params_), 0.1 * params_.ball.radius);
  const physics::CueStroke level{2.0, 0.3, 0.0, 0.0, 0.0};
  for (const double limit : {kMaxHopOnTheCloth, TableMaxHop(params_)}) {
    EXPECT_TRUE(std::isinf(HopFreeSpeed(level, {1.0, 0.6}, params_, limit)));
    EXPECT_EQ(HopReason(level, {1.0, 0.6}, params_, limit), "");
    physics::CueStroke raised{5.0, 0.3, 0.004, -0.005, 25.0 * kDegree};
    raised.speed = HopFreeSpeed(raised, {1.0, 0.6}, params_, limit);
    EXPECT_NEAR(HopHeight(raised, {1.0, 0.6}, params_), limit, 1e-12);
    EXPECT_EQ(HopReason(raised, {1.0, 0.6}, params_, limit), "");
    // The fastest stroke found at one heading is one HopReason accepts at any other (the strike's
    // rounding differs from heading to heading).
    for (int i = 0; i < 64; ++i) {
      physics::CueStroke turned = raised;
      turned.heading = i * 2.0 * M_PI / 64;
      EXPECT_EQ(HopReason(turned, {1.0, 0.6}, params_, limit), "") << turned.heading;
    }
    raised.speed *= 1.01;
    EXPECT_NE(HopReason(raised, {1.0, 0.6}, params_, limit).find("would hop the ball"),
              std::string::npos);
  }
}

// The elevation a stroke is played at: level where a level cue clears; the least that clears and
// the margin where the cue must rise over a rail; none where nothing in range clears.
TEST_F(StrokeLimitsTest, TheElevationIsTheLeastThatClearsAndItsMargin) {
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const Robot gantry = params::LoadRobot("gantry");
  const double r = params_.ball.radius, x = table.length / 2;
  const physics::CueStroke down{1.0, -M_PI / 2, 0.0, 0.0, 0.0};  // toward the lower rail
  const physics::CueStroke up{1.0, M_PI / 2, 0.0, 0.0, 0.0};     // the cue over the lower rail
  const std::vector<table::SceneBall> near_rail = {table::AtRest(0, x, r + 0.05)};
  EXPECT_EQ(std::get<double>(ElevationFor(table, r, near_rail, 0, down, gantry)), 0.0);
  const ClearingElevation least = LeastClearingElevation(table, r, near_rail, 0, up, gantry);
  ASSERT_TRUE(least.elevation);
  ASSERT_GT(*least.elevation, 0.0);
  EXPECT_DOUBLE_EQ(std::get<double>(ElevationFor(table, r, near_rail, 0, up, gantry)), *least.elevation + kElevationMargin);
  Robot level_only = gantry;
  level_only.elevation.max = 0.0;
  EXPECT_TRUE(std::holds_alternative<std::string>(ElevationFor(table, r, near_rail, 0, up, level_only)));
}

}  // namespace
}  // namespace billiard::cue
