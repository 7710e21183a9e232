#include "sim/table/rail_contacts.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/table/testing/events.h"

namespace billiard::table {
namespace {

using testing::Event;

// A kick: the cue ball's own cushion before the contact does not count; after it, every ball
// that meets a cushion or a jaw counts once, and a pocket is no rail.
TEST(RailContactsTest, OnlyAfterTheFirstContactEachBallOnce) {
  const std::vector<TableEvent> events = {
      Event(EventType::kBallCushion, 0), Event(EventType::kBallBall, 3, 0),
      Event(EventType::kBallCushion, 3), Event(EventType::kBallJaw, 5),
      Event(EventType::kBallCushion, 3), Event(EventType::kBallPocket, 7),
      Event(EventType::kBallCushion, 0)};
  EXPECT_EQ(BallsToRailAfterFirstContact(events, 0), (std::vector<int>{0, 3, 5}));
}

TEST(RailContactsTest, NoneWithoutAContact) {
  const std::vector<TableEvent> events = {Event(EventType::kBallCushion, 0),
                                          Event(EventType::kBallBall, 2, 4)};
  EXPECT_TRUE(BallsToRailAfterFirstContact(events, 0).empty());
}

// Simulated: the cue ball driven along the long axis into a ball 0.3 m from the foot rail sends
// it to that rail (a straight shot keeps it on the axis, so it meets the rail, not a pocket).
TEST(RailContactsTest, AStraightShotDrivesTheObjectBallToTheRail) {
  const TableGeometry table = BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double y = 0.5 * table.width;
  std::vector<SceneBall> balls = {AtRest(0, table.length - 1.0, y),
                                  AtRest(4, table.length - 0.3, y)};
  balls[0].state[physics::kVx] = 2.0;
  TableSimulation sim(table, params, balls);
  sim.Run(30.0);
  const std::vector<int> railed = BallsToRailAfterFirstContact(sim.events(), 0);
  EXPECT_NE(std::find(railed.begin(), railed.end(), 4), railed.end());
}

}  // namespace
}  // namespace billiard::table
