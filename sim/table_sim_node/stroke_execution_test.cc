#include "sim/table_sim_node/stroke_execution.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/table_sim_node/session_balls.h"

namespace billiard::table_sim_node {
namespace {

cue_command_t Command(double speed, double heading) {
  cue_command_t command{};
  command.status = cue_command_t::STATUS_OK;
  command.cue_speed = speed;
  command.heading = heading;
  command.tip_side = 0.004;
  command.tip_height = -0.003;
  return command;
}

bool Same(const physics::CueStroke& a, const physics::CueStroke& b) {
  return a.speed == b.speed && a.heading == b.heading && a.tip_side == b.tip_side &&
         a.tip_height == b.tip_height && a.elevation == b.elevation;
}

const params::ExecutionNoise& Robot() {
  static const params::ExecutionNoise noise = params::LoadNoise(params::kDefaultNoise);
  return noise;
}

// The noise's stream is not the targets' (seeded with the seed itself): turning the noise on
// leaves the targets as they were.
TEST(NoiseStream, IsItsSeedsOwnAndNotTheTargetsStream) {
  std::mt19937 noise = NoiseStream(5), again = NoiseStream(5), targets(5);
  const std::uint32_t first = noise();
  EXPECT_EQ(first, again());
  EXPECT_NE(first, targets());
  EXPECT_NE(first, NoiseStream(6)());
}

TEST(StrokeExecution, WithoutNoiseExecutesTheStrokeAsCommanded) {
  StrokeExecution execution(params::ExecutionNoise{}, 0.028575, 1);
  const physics::CueStroke stroke = execution.Executed(Command(3.0, 0.7));
  EXPECT_TRUE(Same(stroke, {3.0, 0.7, 0.004, -0.003, 0.0}));
}

// The same seed executes the same commands the same way, stroke after stroke; another seed
// otherwise. The robot's noise is small: a few per cent of the speed, a degree of heading.
TEST(StrokeExecution, TheSameSeedExecutesTheSameCommandsTheSameWay) {
  StrokeExecution a(Robot(), 0.028575, 3), b(Robot(), 0.028575, 3), c(Robot(), 0.028575, 4);
  for (int k = 0; k < 5; ++k) {
    const cue_command_t command = Command(2.0 + 0.5 * k, 0.3 * k);
    const physics::CueStroke sa = a.Executed(command), sb = b.Executed(command);
    const physics::CueStroke sc = c.Executed(command);
    EXPECT_TRUE(Same(sa, sb)) << k;
    EXPECT_FALSE(Same(sa, sc)) << k;
    EXPECT_FALSE(Same(sa, {command.cue_speed, command.heading, command.tip_side, command.tip_height,
                           command.elevation}))
        << k;
    EXPECT_NEAR(sa.speed, command.cue_speed, 0.2 * command.cue_speed);
    EXPECT_NEAR(sa.heading, command.heading, 0.05);
  }
}

// What the robot drew is what its noise says over many strokes (the root mean square of 4000
// normal draws is within 1.1 % of their spread, one standard error; 5 % is 4.5 of them), and
// nothing before a stroke or without noise.
TEST(StrokeExecution, DrawsTheNoisesSpreadsOverManyStrokes) {
  StrokeExecution quiet(params::ExecutionNoise{}, 0.028575, 1);
  EXPECT_EQ(quiet.Drawn().strokes, 0);
  quiet.Executed(Command(2.0, 0.1));
  EXPECT_EQ(quiet.Drawn().strokes, 1);
  EXPECT_EQ(quiet.Drawn().heading, 0.0);
  EXPECT_EQ(quiet.Drawn().tip, 0.0);

  constexpr int kStrokes = 4000;
  StrokeExecution execution(Robot(), 0.028575, 7);
  for (int k = 0; k < kStrokes; ++k) execution.Executed(Command(1.0 + 0.001 * k, 0.001 * k));
  const DrawnNoise drawn = execution.Drawn();
  EXPECT_EQ(drawn.strokes, kStrokes);
  EXPECT_NEAR(drawn.speed_fraction, Robot().speed, 0.05 * Robot().speed);
  EXPECT_NEAR(drawn.heading, Robot().heading, 0.05 * Robot().heading);
  EXPECT_NEAR(drawn.tip, Robot().tip_offset, 0.05 * Robot().tip_offset);
}

// A refusal strikes nothing and draws no noise; a command strikes the cue ball alone.
TEST(StrokeExecution, StrikesTheCueBallAloneAndNothingOnARefusal) {
  const physics::ModelParameters plant = params::LoadParameters("pool");
  std::vector<table::SceneBall> balls(2);
  balls[0].id = 4;
  balls[0].state.head<2>() = Eigen::Vector2d(1.5, 0.6);
  balls[1].id = kCueBall;
  balls[1].state.head<2>() = Eigen::Vector2d(0.6, 0.6);
  StrokeExecution execution(Robot(), plant.ball.radius, 2), twin(Robot(), plant.ball.radius, 2);

  cue_command_t refusal = Command(3.0, 0.0);
  refusal.status = cue_command_t::STATUS_UNREACHABLE;
  const std::vector<table::SceneBall> unstruck = execution.Struck(balls, refusal, plant);
  EXPECT_EQ(unstruck[1].state, balls[1].state);

  const std::vector<table::SceneBall> struck = execution.Struck(balls, Command(3.0, 0.0), plant);
  EXPECT_EQ(struck[0].state, balls[0].state);
  EXPECT_EQ(struck[1].state,
            physics::StrikeBall(twin.Executed(Command(3.0, 0.0)), {0.6, 0.6}, plant));
}

// The table played to rest: every ball rests or has dropped, and the same strike plays the same.
TEST(PlayedToRest, RunsTheTableUntilEveryBallRestsTheSameEveryTime) {
  const physics::ModelParameters plant = params::LoadParameters("pool");
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::vector<table::SceneBall> balls(2);
  balls[0].id = 4;
  balls[0].state.head<2>() = Eigen::Vector2d(1.5, 0.6);
  balls[1].id = kCueBall;
  balls[1].state = physics::StrikeBall({3.0, 0.1, 0.0, 0.0, 0.0}, {0.6, 0.6}, plant);
  const table::TableSimulation a = PlayedToRest(geometry, plant, balls, SceneMotion(plant));
  const table::TableSimulation b = PlayedToRest(geometry, plant, balls, SceneMotion(plant));
  ASSERT_EQ(a.ball_count(), 2u);
  for (std::size_t i = 0; i < a.ball_count(); ++i) {
    if (!a.pocket(i)) {
      EXPECT_LT(a.State(i).tail<5>().norm(), 1e-9) << i;
    }
    EXPECT_EQ(a.State(i), b.State(i)) << i;
  }
  EXPECT_EQ(a.events().size(), b.events().size());
}

// The robot refuses what its cue cannot make, as FastFiz does: a level stroke from a ball frozen
// to the lower rail and struck away from it lays the cue across the rail; a stroke through a ball
// just behind the cue ball meets that ball; a stroke beyond the robot's speed is out of range.
// Raised clear of the rail, or in the open, the stroke is made.
TEST(Unmakeable, RefusesAStrokeWhoseCueMeetsARailOrABallAndNoOther) {
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const double r = params::LoadParameters("pool").ball.radius;
  const cue::Robot gantry = params::LoadRobot("gantry");
  const double up = M_PI / 2;  // away from the lower rail
  const std::vector<table::SceneBall> frozen{table::AtRest(kCueBall, 1.0, r + 1e-4)};
  const std::string rail = Unmakeable(gantry, geometry, r, frozen, {2.0, up, 0.0, 0.0, 0.0});
  EXPECT_NE(rail.find("lower rail"), std::string::npos) << rail;
  EXPECT_EQ(Unmakeable(gantry, geometry, r, frozen, {2.0, up, 0.0, 0.0, 45.0 * M_PI / 180}), "");
  const std::vector<table::SceneBall> behind{table::AtRest(kCueBall, 1.0, 0.6), table::AtRest(3, 1.0, 0.6 - 2.2 * r)};
  const std::string ball = Unmakeable(gantry, geometry, r, behind, {2.0, up, 0.0, 0.0, 0.0});
  EXPECT_NE(ball.find("ball 3"), std::string::npos) << ball;
  EXPECT_EQ(Unmakeable(gantry, geometry, r, behind, {2.0, -up, 0.0, 0.0, 0.0}), "");
  EXPECT_NE(Unmakeable(gantry, geometry, r, behind, {9.0, -up, 0.0, 0.0, 0.0}), "");
}

}  // namespace
}  // namespace billiard::table_sim_node
