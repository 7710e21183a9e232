// A ball off the cloth on the table (physics/hop.h through the events): its bounces' times against
// projectile motion, a straight flight, the slide's end that friction reaches whatever its timing,
// and an impact in the air that leaves the flight as it was.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/table_simulation.h"

namespace billiard::table {
namespace {

using physics::BallState;
using physics::kVx;
using physics::kX;
using physics::MakeBallState;

physics::ModelParameters Pool() { return params::LoadParameters("pool"); }
TableGeometry Pool9() { return BuildTable(params::LoadTableSpec("pool-9ft")); }

std::vector<TableEvent> Landings(const TableSimulation& sim) {
  std::vector<TableEvent> out;
  for (const TableEvent& e : sim.events()) {
    if (e.type == EventType::kTransition && e.from == MotionPhase::kAirborne) out.push_back(e);
  }
  return out;
}

TEST(Airborne, ARollingBallBouncesAtTheTimesOfProjectileMotionAndFliesStraight) {
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius, g = p.ball.gravity, up = 0.3;
  SceneBall ball{0, MakeBallState(0.5, 0.6, 1.0, 0.0, 0.0, 1.0 / r, 0.0)};
  ball.flight.vertical_speed = up;
  TableSimulation sim(Pool9(), p, {ball});
  sim.Run(1.0);
  const std::vector<TableEvent> landings = Landings(sim);
  // Bounces of up, e up, e^2 up, ... until one would rise less than kSettledHop.
  double t = 0.0, v = up;
  std::size_t bounces = 0;
  for (; physics::Airborne({0.0, v}, g); v *= physics::kBedRestitution, ++bounces) {
    t += 2.0 * v / g;
    ASSERT_LT(bounces, landings.size());
    EXPECT_NEAR(landings[bounces].time, t, 1e-12);
  }
  EXPECT_EQ(landings.size(), bounces);
  EXPECT_EQ(landings.back().to, MotionPhase::kRolling);
  // Rolling, the landings have no slip to act on: the flight is at the launch's velocity.
  EXPECT_NEAR(sim.StateAt(0, t)[kX], 0.5 + 1.0 * t, 1e-12);
  EXPECT_NEAR(sim.StateAt(0, t)[kVx], 1.0, 1e-12);
}

TEST(Airborne, ASlideEndsAtTheSameRollingVelocityWithOrWithoutAHopButFurtherOn) {
  // Friction against a slip of fixed direction moves the state along one line, whether it acts on
  // the cloth or at landings: the slide ends where the slip vanishes (v = 5/7 v0 for a stun shot).
  const physics::ModelParameters p = Pool();
  const BallState stun = MakeBallState(0.4, 0.6, 2.0, 0.0, 0.0, 0.0, 0.0);
  const auto rolling_start = [&](double up) {
    SceneBall ball{0, stun};
    ball.flight.vertical_speed = up;
    TableSimulation sim(Pool9(), p, {ball});
    sim.RunUntil([](const TableEvent& e) { return e.to == MotionPhase::kRolling; });
    return sim.State(0);
  };
  const BallState flat = rolling_start(0.0), hopped = rolling_start(0.2);
  EXPECT_NEAR(flat[kVx], 5.0 / 7.0 * 2.0, 1e-12);
  EXPECT_NEAR(hopped[kVx], 5.0 / 7.0 * 2.0, 1e-12);
  // In the air no friction acts, and the landings' impulses take less than the cloth would in
  // that time ((1 + e) / 2 of it): the hopping ball slides on further.
  EXPECT_GT(hopped[kX], flat[kX] + 0.01);
}

TEST(Airborne, AnImpactInTheAirLeavesTheFlightAsItWas) {
  const physics::ModelParameters p = Pool();
  const double r = p.ball.radius, g = p.ball.gravity, up = 0.4;
  SceneBall cue{0, MakeBallState(0.5, 0.6, 2.0, 0.0, 0.0, 2.0 / r, 0.0)};
  cue.flight.vertical_speed = up;
  // Met 2 cm later, long before the first landing (82 ms, 16 cm).
  const SceneBall object = AtRest(1, 0.5 + 2.0 * r + 0.02, 0.6);
  TableSimulation sim(Pool9(), p, {cue, object});
  sim.Run(0.05);
  ASSERT_FALSE(sim.events().empty());
  EXPECT_EQ(sim.events().front().type, EventType::kBallBall);
  EXPECT_EQ(sim.segments(0).back().phase(), MotionPhase::kAirborne);
  sim.Run();
  const std::vector<TableEvent> landings = Landings(sim);
  ASSERT_FALSE(landings.empty());
  EXPECT_NEAR(landings.front().time, 2.0 * up / g, 1e-12);
}

}  // namespace
}  // namespace billiard::table
