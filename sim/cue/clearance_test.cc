#include "sim/cue/clearance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/params/table_specs.h"

namespace billiard::cue {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kR = 0.028575;  // the pool ball
constexpr double kTipRadius = 0.0065;
// The bisection's resolution is 1e-9 rad; the analytic elevations are met well within this.
constexpr double kElevationTolerance = 1e-8;

// A robot without a body holding a cue of `length` from a 13 mm tip to a `butt_radius` butt,
// raising it anywhere in [0, 80] degrees.
Robot Free(double length, double butt_radius) {
  Robot robot;
  robot.name = "test";
  robot.cue = {length, kTipRadius, butt_radius};
  robot.bridge = 0.2;
  robot.elevation = {0.0, 80 * kDegree};
  robot.max_tip_offset = 0.5;
  robot.speed = {0.0, 8.0};
  return robot;
}

table::SceneBall Ball(int id, double x, double y) {
  table::SceneBall ball;
  ball.id = id;
  ball.state[0] = x;
  ball.state[1] = y;
  return ball;
}

physics::CueStroke Stroke(double heading, double elevation = 0.0, double side = 0.0,
                          double height = 0.0) {
  return {2.0, heading, side, height, elevation};
}

// The least elevation at which a centre stroke's tapered rod, its axis through the ball's
// centre, passes over an edge (a horizontal line across the stroke's vertical plane) `a`
// behind the centre and at height `h` above the cloth, touching it with its side: in that
// plane, with u = (cos e, sin e) the axis's back direction and the tip R along it from the
// centre, the edge lies rho = a sin e - (h - R) cos e across the axis and s = a cos e +
// (h - R) sin e - R along it from the tip, and the side touches it where
// rho sqrt(1 - k^2) = r0 + k s (rod_distance.h): A sin e - B cos e = r0 - k R with
// A = a sqrt(1 - k^2) - k (h - R), B = (h - R) sqrt(1 - k^2) + k a.
struct EdgeTangent {
  double elevation, along;  // the elevation, and where along the axis the side touches
};
EdgeTangent OverEdge(double a, double h, const CueShape& cue) {
  const double k = cue.Taper(), c = std::sqrt(1 - k * k), z = h - kR;
  const double A = a * c - k * z, B = z * c + k * a;
  const double e = std::atan2(B, A) + std::asin((cue.tip_radius - k * kR) / std::hypot(A, B));
  const double rho = a * std::sin(e) - z * std::cos(e);
  const double s = a * std::cos(e) + z * std::sin(e) - kR;
  return {e, s + k * rho / c};
}

class ClearanceTest : public ::testing::Test {
 protected:
  ClearanceTest() : table_(table::BuildTable(params::LoadTableSpec(params::kDefaultTable))) {}
  double Least(const std::vector<table::SceneBall>& balls, const physics::CueStroke& stroke,
               const Robot& robot) const {
    const ClearingElevation found = LeastClearingElevation(table_, kR, balls, 0, stroke, robot);
    EXPECT_TRUE(found.elevation.has_value()) << found.reason;
    EXPECT_TRUE(found.clearance.clears);
    return found.elevation.value_or(NAN);
  }
  table::TableGeometry table_;
};

// A short cue in the middle of the table reaches no rail and no ball: level, its lowest point
// is its butt's underside, R - r1 over the cloth.
TEST_F(ClearanceTest, InTheOpenALevelCueClears) {
  const Robot robot = Free(0.5, 0.009);
  const std::vector<table::SceneBall> balls = {Ball(0, 1.27, 0.635)};
  for (double heading : {0.0, 37 * kDegree, 90 * kDegree, 200 * kDegree}) {
    const CueClearance level = Clearance(table_, kR, balls, 0, Stroke(heading), robot);
    EXPECT_TRUE(level.clears);
    EXPECT_EQ(level.nearest, Obstacle::kTable);
    EXPECT_EQ(level.what, "the cloth");
    EXPECT_NEAR(level.distance, kR - 0.009, 1e-12);
    EXPECT_EQ(Least(balls, Stroke(heading), robot), 0.0);
  }
}

// A ball frozen to the lower rail: driven into it, the cue lies over the open table and clears
// level; driven away from it, the cue passes over the rail, and its side must clear the rail's
// top edge, R behind the centre at the rail's height. A line through the centre (FastFiz's cue,
// without thickness) needs only atan((h - R) / R).
TEST_F(ClearanceTest, FrozenToARailOverItNeedsTheAnalyticElevation) {
  const Robot player = Free(1.47, 0.0155), short_cue = Free(0.5, 0.009);
  const std::vector<table::SceneBall> balls = {Ball(0, 1.0, kR)};
  EXPECT_TRUE(Clearance(table_, kR, balls, 0, Stroke(-M_PI / 2), short_cue).clears);
  EXPECT_EQ(Least(balls, Stroke(-M_PI / 2), short_cue), 0.0);

  const CueClearance level = Clearance(table_, kR, balls, 0, Stroke(M_PI / 2), player);
  EXPECT_FALSE(level.clears);
  EXPECT_EQ(level.what, "the lower rail");
  const EdgeTangent tangent = OverEdge(kR, table_.rail_height, player.cue);
  ASSERT_GT(tangent.along, 0.0) << "the side, not the tip's cap, touches the edge";
  const double least = Least(balls, Stroke(M_PI / 2), player);
  EXPECT_NEAR(least, tangent.elevation, kElevationTolerance);
  // Where the side touches the edge: the clearance at the least elevation says the same point.
  const CueClearance at_least = Clearance(table_, kR, balls, 0, Stroke(M_PI / 2, least), player);
  EXPECT_EQ(at_least.what, "the lower rail");
  EXPECT_NEAR(at_least.along, tangent.along, 1e-6);
  EXPECT_GT(least, std::atan((table_.rail_height - kR) / kR));
  EXPECT_NEAR(least / kDegree, 34.0, 0.1);  // what a player raises the cue to, off a rail
}

// Farther from the rail, less elevation; each the analytic one, each above the line's.
TEST_F(ClearanceTest, AFartherRailNeedsLess) {
  const Robot player = Free(1.47, 0.0155);
  double previous = M_PI / 2;
  for (double a : {kR, 0.05, 0.1, 0.2, 0.4}) {
    SCOPED_TRACE(a);
    const double least = Least({Ball(0, 1.0, a)}, Stroke(M_PI / 2), player);
    const EdgeTangent tangent = OverEdge(a, table_.rail_height, player.cue);
    ASSERT_GT(tangent.elevation, std::asin(player.cue.Taper()))
        << "the rod rises going back: its near edge, not its far one, is nearest";
    EXPECT_NEAR(least, tangent.elevation, kElevationTolerance);
    EXPECT_GT(least, std::atan((table_.rail_height - kR) / a));
    EXPECT_LT(least, previous);
    previous = least;
  }
}

// A long cue from a ball frozen to one rail, driven into it, crosses the other rail.
TEST_F(ClearanceTest, ALongCueCrossesTheFarRail) {
  const Robot player = Free(1.47, 0.0155);
  const double least = Least({Ball(0, 1.0, kR)}, Stroke(-M_PI / 2), player);
  EXPECT_NEAR(least, OverEdge(table_.width - kR, table_.rail_height, player.cue).elevation,
              kElevationTolerance);
}

// A ball d behind the cue ball's centre, on the cue's line: the rod's side is tangent to it
// where rho sqrt(1 - k^2) - r0 - k s = R, rho = d sin e, s = d cos e - R: with k = sin b,
// d sin(e - b) = r0 + R (1 - k), so e = asin(k) + asin((r0 + R (1 - k)) / d). Level, the ball
// sits on the axis, as deep in the rod as r(d - R) + R.
TEST_F(ClearanceTest, ABallBehindNeedsTheTangentElevation) {
  const Robot robot = Free(1.0, 0.0126);  // reaches no rail from the middle of the table
  const double k = robot.cue.Taper();
  const double x = 1.27, y = 0.635;
  double previous = M_PI / 2;
  for (double d : {0.06, 0.1, 0.2, 0.4, 0.8}) {
    SCOPED_TRACE(d);
    const std::vector<table::SceneBall> balls = {Ball(0, x, y), Ball(1, x - d, y)};
    const CueClearance level = Clearance(table_, kR, balls, 0, Stroke(0.0), robot);
    EXPECT_FALSE(level.clears);
    EXPECT_EQ(level.nearest, Obstacle::kBall);
    EXPECT_EQ(level.ball, 1);
    EXPECT_EQ(level.what, "ball 1");
    EXPECT_NEAR(level.distance, -(robot.cue.RadiusAt(d - kR) + kR), 1e-12);
    EXPECT_NEAR(level.along, d - kR, 1e-12) << "the ball's centre lies on the axis, d - R from the tip";

    const double expected = std::asin(k) + std::asin((kTipRadius + kR * (1 - k)) / d);
    const double least = Least(balls, Stroke(0.0), robot);
    EXPECT_NEAR(least, expected, kElevationTolerance);
    EXPECT_LT(least, previous) << "a farther blocker needs less";
    previous = least;
  }
}

// Low draw with a level cue puts the butt's underside below the cloth. The butt's centre is at
// R + t cos e + (sqrt(R^2 - t^2) + L) sin e (the tip at P = b - sqrt(R^2 - t^2) c, the axis
// rising L sin e to the butt); its underside leaves the cloth at A sin e + t cos e = r1 - R,
// A = sqrt(R^2 - t^2) + L. (Snooker's table: a 1.47 m cue from its middle reaches no rail.)
TEST_F(ClearanceTest, LowDrawLiftsTheButtOffTheCloth) {
  const table::TableGeometry snooker = table::BuildTable(params::LoadTableSpec("snooker-12ft"));
  const double R = 0.02625, t = -0.5 * R;
  const Robot player = Free(1.47, 0.0155);
  const std::vector<table::SceneBall> balls = {Ball(0, snooker.length / 2, snooker.width / 2)};
  const CueClearance level = Clearance(snooker, R, balls, 0, Stroke(0.0, 0.0, 0.0, t), player);
  EXPECT_EQ(level.what, "the cloth");
  EXPECT_NEAR(level.distance, R + t - 0.0155, 1e-12);

  const double A = std::sqrt(R * R - t * t) + player.cue.length;
  const double expected = std::asin((0.0155 - R) / std::hypot(A, t)) - std::atan2(t, A);
  ASSERT_LT(std::sin(expected), player.cue.Taper()) << "the butt, not the tip, is lowest";
  const ClearingElevation found =
      LeastClearingElevation(snooker, R, balls, 0, Stroke(0.0, 0.0, 0.0, t), player);
  ASSERT_TRUE(found.elevation.has_value());
  EXPECT_NEAR(*found.elevation, expected, kElevationTolerance);
}

// A gantry's carriage, R + bridge behind the centre along the axis, must rise to its clearance:
// R + (R + bridge) sin e >= clearance. Its butt must stay within the rectangle: from a ball a
// behind the lower nose, (R + L) cos e <= a + overhang.
TEST_F(ClearanceTest, AGantrysLimits) {
  Robot gantry = Free(0.5, 0.009);
  gantry.gantry = Gantry{0.6, 0.05};
  const std::vector<table::SceneBall> middle = {Ball(0, 1.27, 0.635)};
  EXPECT_EQ(Clearance(table_, kR, middle, 0, Stroke(0.3), gantry).what,
            "the carriage below its clearance");
  EXPECT_NEAR(Least(middle, Stroke(0.3), gantry), std::asin((0.05 - kR) / (kR + 0.2)),
              kElevationTolerance);

  gantry.cue = {0.74, kTipRadius, 0.0108};
  gantry.gantry = Gantry{0.1, 0.0};
  const double a = 0.3;
  EXPECT_NEAR(Least({Ball(0, 1.27, a)}, Stroke(M_PI / 2), gantry),
              std::acos((a + 0.1) / (kR + 0.74)), kElevationTolerance);
}

// The table mirrored across either middle line, with the stroke mirrored (the heading
// reflected, right english turned left), needs the same elevation.
TEST_F(ClearanceTest, MirroredScenesNeedTheSameElevation) {
  const Robot player = Free(1.47, 0.0155);
  const double L = table_.length, W = table_.width;
  std::mt19937_64 engine(47);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int blocked = 0;
  for (int scene = 0; scene < 40; ++scene) {
    std::vector<table::SceneBall> balls = {
        Ball(0, kR + (L - 2 * kR) * unit(engine), kR + (W - 2 * kR) * unit(engine))};
    while (balls.size() < 7) {  // balls near the cue ball, none overlapping
      const double x = balls[0].state[0] + 0.6 * (unit(engine) - 0.5);
      const double y = balls[0].state[1] + 0.6 * (unit(engine) - 0.5);
      bool free = table_.OnSurface({x, y}, kR);
      for (const table::SceneBall& b : balls) {
        free = free && std::hypot(x - b.state[0], y - b.state[1]) > 2 * kR;
      }
      if (free) balls.push_back(Ball(static_cast<int>(balls.size()), x, y));
    }
    const physics::CueStroke stroke =
        Stroke(2 * M_PI * unit(engine), 0.0, 0.4 * kR * (unit(engine) - 0.5),
               0.4 * kR * (unit(engine) - 0.5));
    const ClearingElevation plain = LeastClearingElevation(table_, kR, balls, 0, stroke, player);
    std::vector<table::SceneBall> across = balls, along = balls;
    for (table::SceneBall& b : across) b.state[1] = W - b.state[1];
    for (table::SceneBall& b : along) b.state[0] = L - b.state[0];
    physics::CueStroke across_stroke = stroke, along_stroke = stroke;
    across_stroke.heading = -stroke.heading;
    along_stroke.heading = M_PI - stroke.heading;
    across_stroke.tip_side = along_stroke.tip_side = -stroke.tip_side;
    for (const ClearingElevation& mirrored :
         {LeastClearingElevation(table_, kR, across, 0, across_stroke, player),
          LeastClearingElevation(table_, kR, along, 0, along_stroke, player)}) {
      ASSERT_EQ(mirrored.elevation.has_value(), plain.elevation.has_value()) << scene;
      if (plain.elevation) {
        EXPECT_NEAR(*mirrored.elevation, *plain.elevation, 1e-8) << scene;
      }
    }
    blocked += plain.elevation.value_or(1.0) > 0.0;
  }
  EXPECT_GT(blocked, 10) << "the scenes should test the search, not only level strokes";
}

// A ball frozen behind the cue ball needs asin(k) + asin((r0 + R (1 - k)) / 2R), about 38
// degrees: a robot that rises to 30 cannot play it, and says why.
TEST_F(ClearanceTest, NothingInRangeClearsAndSaysWhy) {
  Robot robot = Free(1.0, 0.0126);
  robot.elevation.max = 30 * kDegree;
  const std::vector<table::SceneBall> balls = {Ball(0, 1.27, 0.635), Ball(1, 1.27 - 2 * kR, 0.635)};
  const ClearingElevation found = LeastClearingElevation(table_, kR, balls, 0, Stroke(0.0), robot);
  EXPECT_FALSE(found.elevation.has_value());
  EXPECT_EQ(found.clearance.ball, 1);
  EXPECT_EQ(found.reason.rfind("nothing in the robot's elevations [0, 30] deg clears: at 30 deg "
                               "ball 1 is ",
                               0),
            0u)
      << found.reason;
  EXPECT_NE(found.reason.find(" mm into the cue"), std::string::npos) << found.reason;
}

TEST_F(ClearanceTest, RefusesAStrokeWithoutItsBall) {
  const Robot robot = Free(1.0, 0.0126);
  EXPECT_THROW(Clearance(table_, kR, {Ball(1, 1.0, 0.5)}, 0, Stroke(0.0), robot),
               std::invalid_argument);
  EXPECT_THROW(Clearance(table_, kR, {Ball(0, 1.0, 0.5)}, 0, Stroke(0.0, 0.0, kR), robot),
               std::invalid_argument);
}

}  // namespace
}  // namespace billiard::cue
