#include "sim/table_sim_node/session_balls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"

namespace billiard::table_sim_node {
namespace {

constexpr double kRadius = 0.028575;

table::TableGeometry Pool() {
  return table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
}

TEST(SessionBalls, AnObjectBallsClassIsItsNumberAndTheCueBallsIsCue) {
  EXPECT_EQ(TruthClass(kCueBall), ball_state_t::CLASS_CUE);
  EXPECT_EQ(TruthClass(9), 9);
  EXPECT_EQ(TruthClass(15), 15);
}

TEST(SessionBalls, FindsABallByItsIdAndTheObjectBallNearestTheCueBall) {
  const std::vector<table::SceneBall> balls = {table::AtRest(3, 2.0, 0.6), table::AtRest(kCueBall, 0.5, 0.6),
                                               table::AtRest(7, 0.9, 1.0), table::AtRest(5, 1.0, 0.6)};
  EXPECT_EQ(Find(balls, 7)->id, 7);
  EXPECT_EQ(Find(balls, 8), balls.end());
  EXPECT_EQ(NearestObjectBall(balls, "s").id, 5);  // 0.5 m away; ball 7 is 0.57 m
  try {
    NearestObjectBall({table::AtRest(kCueBall, 0.5, 0.6)}, "lonely.json");
    ADD_FAILURE() << "no object ball, no throw";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "lonely.json: no ball to strike at");
  }
}

TEST(SessionBalls, TheNearestPocketOfAPointIsTheCornerOrSideItLiesBy) {
  const table::TableGeometry table = Pool();
  EXPECT_EQ(NearestPocket(table, {0.02, 0.03}), "lower_left");
  EXPECT_EQ(NearestPocket(table, {0.5 * table.length + 0.01, 0.02}), "lower_middle");
  EXPECT_EQ(NearestPocket(table, {table.length, table.width}), "upper_right");
}

// A ball rolled softly down the upper right corner's diagonal: at some speeds the model leaves
// it at rest past the mouth line, in the jaws, where a real one drops. The outcome drops it in
// that pocket (the cue ball: a scratch; an object ball: a pot, the called one's if called
// there), as the planner's own games do (choice::PlayToRest); one resting short of the line, or
// frozen to a rail, stays.
TEST(SessionBalls, ABallStoppingInTheJawsDropsThereAndOneFrozenToARailStays) {
  const table::TableGeometry table = Pool();
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::Pocket& corner = *table.PocketNamed("upper_right");
  const Eigen::Vector2d from = corner.centre - 0.8 * Eigen::Vector2d(1.0, 1.0).normalized();
  const table::SceneBall frozen = table::AtRest(9, 0.6, params.ball.radius);  // on the bottom rail
  int hanging = 0;
  for (const int id : {kCueBall, 5}) {
    for (double speed = 0.30; speed < 1.2; speed += 0.01) {
      table::TableSimulation sim(
          table, params,
          {table::Struck(id, {speed, std::atan2(1.0, 1.0), 0, 0, 0}, from, params), frozen});
      sim.Run(60.0);
      const bool in_the_jaws = !sim.pocket(0) && table.PocketPastMouth(sim.State(0).head<2>());
      const bool dropped = sim.pocket(0).has_value() || in_the_jaws;
      hanging += in_the_jaws;
      const TableOutcome outcome = OutcomeOf(sim, table, 5, "upper_right");
      EXPECT_EQ(outcome.scratch, id == kCueBall && dropped) << speed;
      EXPECT_EQ(outcome.called_potted, id == 5 && dropped) << speed;
      EXPECT_EQ(outcome.potted, id == 5 && dropped ? std::vector<int>{5} : std::vector<int>{})
          << speed;
      ASSERT_EQ(outcome.rest.size(), dropped ? 1u : 2u) << speed;
      EXPECT_EQ(outcome.rest.back().id, 9);
      EXPECT_EQ(outcome.rest.back().state.head<2>(), frozen.state.head<2>());
    }
  }
  EXPECT_GT(hanging, 0) << "no speed stops a ball in the jaws: the test shows nothing";
}

// After a scratch the cue ball goes on the head spot (x = 1/4 length, the middle of the width);
// a ball there sends it toward the head rail, clear of that ball. Its old place, if any, goes.
TEST(SessionBalls, TheCueBallGoesBackOnTheHeadSpotOrBehindIt) {
  const table::TableGeometry table = Pool();
  const Eigen::Vector2d head_spot(0.25 * table.length, 0.5 * table.width);
  const std::vector<table::SceneBall> free =
      InTheKitchen(table, kRadius, {table::AtRest(kCueBall, 2.0, 0.3), table::AtRest(4, 1.5, 0.6)});
  ASSERT_EQ(free.size(), 2u);
  EXPECT_EQ(Find(free, kCueBall)->state.head<2>(), head_spot);

  const std::vector<table::SceneBall> blocked =
      InTheKitchen(table, kRadius, {table::AtRest(4, head_spot.x(), head_spot.y())});
  ASSERT_EQ(blocked.size(), 2u);
  const Eigen::Vector2d cue = Find(blocked, kCueBall)->state.head<2>();
  EXPECT_LT(cue.x(), head_spot.x());
  EXPECT_EQ(cue.y(), head_spot.y());
  EXPECT_GE(head_spot.x() - cue.x(), 2.0 * kRadius + kPlacementClearance);
  EXPECT_LT(head_spot.x() - cue.x(), 2.0 * kRadius + kPlacementClearance + kPlacementStep);
}

}  // namespace
}  // namespace billiard::table_sim_node
