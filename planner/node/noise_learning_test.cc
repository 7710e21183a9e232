#include "planner/node/noise_learning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/synthetic_shots.h"

namespace billiard::planner_node {
namespace {

constexpr double kDegree = M_PI / 180.0;

cue_command_t Command(std::int64_t utime, const physics::CueStroke& s) {
  cue_command_t c{};
  c.utime = utime;
  c.status = cue_command_t::STATUS_OK;
  c.cue_speed = s.speed;
  c.heading = s.heading;
  c.tip_side = s.tip_side;
  c.tip_height = s.tip_height;
  c.elevation = s.elevation;
  return c;
}

// A robot whose heading and speed spreads are 2.5 times the prior's (0.25 degree, 2.5 %), its
// tip's the prior's: the learner, fed its commands and the shots tracked after them (30 Hz, half
// a millimetre), plans for the prior until ten launches, then for spreads within a quarter of
// the robot's; a stroke after a placement in hand is not learned from.
TEST(NoiseLearner, LearnsTheRobotsSpreadsFromItsStrokes) {
  const physics::ModelParameters p = params::LoadParameters("pool");
  const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const params::ExecutionNoise prior = params::LoadNoise(params::kDefaultNoise);
  params::ExecutionNoise robot = prior;
  robot.heading = 0.25 * kDegree;
  robot.speed = 0.025;
  NoiseLearner learner(prior);
  std::mt19937_64 random(11);
  std::normal_distribution<double> unit;
  std::vector<shot_fit::TrackedShot> shots;
  std::vector<std::int64_t> strikes;
  bool learned_early = false;
  for (shot_fit::SyntheticScene scene : shot_fit::SyntheticScenes(table, p.ball.radius, 300, 11)) {
    const std::int64_t utime = 1000000 * static_cast<std::int64_t>(shots.size() + 1);
    cue_command_t command = Command(utime, scene.strike.stroke);
    command.has_cue_placement = shots.size() % 10 == 9;  // learned from: never
    learner.Commanded(command);
    scene.strike.stroke = params::Perturbed(scene.strike.stroke, robot, p.ball.radius,
                                            [&] { return unit(random); });
    if (command.has_cue_placement) scene.strike.stroke.heading += 10.0 * kDegree;
    shots.push_back(shot_fit::SimulateTrackedShot(table, p, scene.starts, 0, scene.strike, 0.6,
                                                  1.0 / 30.0, 5e-4, 0.002, random()));
    strikes.push_back(utime);
    const bool learned = learner.Learn(shots, strikes, p);
    if (learner.launches() < kMinNoiseShots) {
      learned_early = learned_early || learned;
      EXPECT_EQ(learner.noise().heading, prior.heading);
    }
  }
  EXPECT_FALSE(learned_early);
  ASSERT_TRUE(learner.fit().has_value());
  const shot_fit::NoiseFit& fit = *learner.fit();
  EXPECT_EQ(learner.shots_seen(), shots.size());
  EXPECT_GE(learner.launches(), 100u);
  EXPECT_LE(learner.launches(), shots.size() * 9 / 10);  // the placements left out
  EXPECT_EQ(fit.rejected, 0u);
  EXPECT_NEAR(learner.noise().heading, robot.heading, 0.25 * robot.heading);
  EXPECT_NEAR(learner.noise().speed, robot.speed, 0.25 * robot.speed);
  EXPECT_LE(fit.heading.lower, robot.heading);
  EXPECT_GE(fit.heading.upper, robot.heading);
  EXPECT_EQ(learner.noise().name, "robot-learned");
  EXPECT_NE(learner.Describe().find("learned noise from"), std::string::npos);
}

}  // namespace
}  // namespace billiard::planner_node
