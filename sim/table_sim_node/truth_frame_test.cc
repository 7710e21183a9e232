#include "sim/table_sim_node/truth_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "lcmtypes/billiard/ball_state_t.hpp"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/physics/cue_strike.h"

namespace billiard::table_sim_node {
namespace {

TruthBall Moving(int id) {
  return {id, [id](double t) {
            return physics::MakeBallState(0.1 * id + t, 0.5, 1.0, 0.0, 0.2, -0.3, 4.0 * id);
          }};
}

// The truth of each ball at the frame's time: its state, its number as its class (the cue
// ball's CLASS_CUE), with full confidence.
TEST(TruthMessage, CarriesEachBallsStateAndClassAtTheFramesTime) {
  const table_state_t truth = TruthMessage({Moving(0), Moving(9)}, 2.0, 2000000);
  EXPECT_EQ(truth.utime, 2000000);
  ASSERT_EQ(truth.num_balls, 2);
  ASSERT_EQ(truth.balls.size(), 2u);
  const ball_state_t& cue = truth.balls[0];
  const ball_state_t& nine = truth.balls[1];
  EXPECT_EQ(cue.ball_class, ball_state_t::CLASS_CUE);
  EXPECT_EQ(nine.ball_class, 9);
  EXPECT_EQ(nine.ball_id, 9);
  EXPECT_EQ(nine.utime, 2000000);
  EXPECT_EQ(nine.class_confidence, 1.0f);
  EXPECT_EQ(nine.position[0], 0.9 + 2.0);
  EXPECT_EQ(nine.position[1], 0.5);
  EXPECT_EQ(nine.velocity[0], 1.0);
  EXPECT_EQ(nine.spin[0], 0.2);
  EXPECT_EQ(nine.spin[1], -0.3);
  EXPECT_EQ(nine.spin[2], 36.0);
}

// The camera sees each ball where its truth is, in pool's colours, the 9-15 striped.
TEST(RenderedBalls, FollowTheTruthInPoolsColoursStripesFromNine) {
  const std::vector<render::RenderBall> shown = RenderedBalls({Moving(0), Moving(8), Moving(9)});
  ASSERT_EQ(shown.size(), 3u);
  EXPECT_FALSE(shown[0].striped);
  EXPECT_FALSE(shown[1].striped);
  EXPECT_TRUE(shown[2].striped);
  EXPECT_EQ(shown[1].colour, render::PoolBallColour(8));
  EXPECT_EQ(shown[2].position(1.5), Eigen::Vector2d(0.9 + 1.5, 0.5));
}

TEST(AtRest, HoldsEachBallStillWhereItIs) {
  table::SceneBall rolling{3, physics::MakeBallState(1.0, 0.4, 2.0, 1.0, 5.0, 6.0, 7.0)};
  const std::vector<TruthBall> still = AtRest({rolling});
  ASSERT_EQ(still.size(), 1u);
  EXPECT_EQ(still[0].id, 3);
  for (double t : {0.0, 10.0})
    EXPECT_EQ(still[0].state(t), physics::MakeBallState(1.0, 0.4, 0, 0, 0, 0, 0));
}

// A shot struck at sim time 10: each ball's truth is the simulation's state since the strike,
// its rest after the simulation's end; a ball that dropped leaves the frames once its fall
// into the pocket begins.
TEST(OnTable, FollowsTheSimulationSinceTheStrikeAndDropsPocketedBalls) {
  const physics::ModelParameters p = params::LoadParameters("pool");
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::vector<table::SceneBall> balls(2);
  balls[0].id = 0;
  balls[0].state = physics::StrikeBall({2.0, -0.75 * M_PI, 0.0, 0.0, 0.0}, {0.3, 0.3}, p);
  balls[1].id = 6;
  balls[1].state.head<2>() = Eigen::Vector2d(1.5, 0.6);
  table::TableSimulation sim(geometry, p, balls);
  sim.Run(30.0);
  ASSERT_TRUE(sim.pocket(0)) << "the cue ball rolls into the lower left pocket";
  constexpr double kStrike = 10.0;

  const std::vector<TruthBall> early = OnTable(sim, kStrike, kStrike + 0.05);
  ASSERT_EQ(early.size(), 2u);
  EXPECT_EQ(early[0].id, 0);
  EXPECT_LT((early[0].state(kStrike + 0.05) - sim.StateAt(0, 0.05)).norm(), 1e-9);
  EXPECT_EQ(early[1].state(kStrike + 1e4), sim.StateAt(1, sim.time()));

  const std::vector<TruthBall> late = OnTable(sim, kStrike, kStrike + 1e3);
  ASSERT_EQ(late.size(), 1u);
  EXPECT_EQ(late[0].id, 6);
}

}  // namespace
}  // namespace billiard::table_sim_node
