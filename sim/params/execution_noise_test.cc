#include "sim/params/execution_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/params/parameter_sets.h"

namespace billiard::params {
namespace {

constexpr double kDegree = M_PI / 180.0;

TEST(ExecutionNoiseTest, BuiltinModelsReadInSiUnits) {
  EXPECT_EQ(BuiltinNoiseNames(), (std::vector<std::string>{"computational-pool", "robot"}));
  const ExecutionNoise robot = LoadNoise(kDefaultNoise);
  EXPECT_EQ(robot.name, "robot");
  EXPECT_DOUBLE_EQ(robot.speed, 0.01);
  EXPECT_DOUBLE_EQ(robot.heading, 0.1 * kDegree);
  EXPECT_DOUBLE_EQ(robot.tip_offset, 0.5e-3);
  const ExecutionNoise pool = LoadNoise("computational-pool");
  EXPECT_DOUBLE_EQ(pool.speed_absolute, 0.075);
  EXPECT_DOUBLE_EQ(pool.elevation, 0.1 * kDegree);
  EXPECT_FALSE(pool.source.empty());
}

TEST(ExecutionNoiseTest, RefusesWhatIsNotAModel) {
  const std::string good =
      R"({"speed_fraction": 0, "speed_mps": 0, "heading_deg": 0.1, "tip_mm": 0, "elevation_deg": 0)";
  EXPECT_NO_THROW(ParseNoise(good + "}", "t.json"));
  EXPECT_THROW(ParseNoise(good + R"(, "extra": 1})", "t.json"), std::invalid_argument);
  EXPECT_THROW(ParseNoise(R"({"speed_fraction": 0})", "t.json"), std::invalid_argument);
  EXPECT_THROW(ParseNoise(R"({"speed_fraction": -1, "speed_mps": 0, "heading_deg": 0.1,
                              "tip_mm": 0, "elevation_deg": 0})",
                          "t.json"),
               std::invalid_argument);
  EXPECT_THROW(LoadNoise("no-such-model"), std::invalid_argument);
}

// The draws land where the model says, in the order it documents.
TEST(ExecutionNoiseTest, PerturbsEachParameterByItsSpread) {
  ExecutionNoise noise = LoadNoise("computational-pool");
  noise.speed = 0.02;
  const physics::CueStroke stroke{2.0, 1.0, 0.0, 0.0, 0.2};
  int draw = 0;
  const physics::CueStroke played =
      Perturbed(stroke, noise, 0.028575, [&] { return static_cast<double>(++draw); });
  EXPECT_DOUBLE_EQ(played.heading, 1.0 + 2 * noise.heading);
  EXPECT_DOUBLE_EQ(played.tip_side, 3 * noise.tip_offset);
  EXPECT_DOUBLE_EQ(played.tip_height, 4 * noise.tip_offset);
  EXPECT_DOUBLE_EQ(played.elevation, 0.2 + 5 * noise.elevation);
  EXPECT_DOUBLE_EQ(played.speed, 2.0 * (1 + 0.02) + 6 * noise.speed_absolute);
  EXPECT_EQ(draw, 6);
  // The robot's model has no elevation or absolute speed spread: four draws, as the table
  // simulator always drew.
  draw = 0;
  Perturbed(stroke, LoadNoise("robot"), 0.028575, [&] { return static_cast<double>(++draw); });
  EXPECT_EQ(draw, 4);
}

TEST(ExecutionNoiseTest, SpreadOfManyStrokesIsTheModels) {
  const ExecutionNoise noise = LoadNoise("robot");
  std::mt19937 rng(3);
  std::normal_distribution<double> unit(0.0, 1.0);
  const int n = 20000;
  double sum_sq = 0;
  for (int i = 0; i < n; ++i) {
    const physics::CueStroke s = Perturbed({1.5, 0.0, 0, 0, 0}, noise, 0.028575, [&] { return unit(rng); });
    sum_sq += s.heading * s.heading;
  }
  // The sample standard deviation of n normals is within 3 / sqrt(2 n) of sigma (3 sigma).
  EXPECT_NEAR(std::sqrt(sum_sq / n) / noise.heading, 1.0, 3.0 / std::sqrt(2.0 * n));
}

TEST(ExecutionNoiseTest, KeepsTheTipOnTheBall) {
  ExecutionNoise noise;
  noise.tip_offset = 1.0;  // far past the ball
  const physics::CueStroke s = Perturbed({1.0, 0, 0, 0, 0}, noise, 0.03, [] { return 1.0; });
  EXPECT_NEAR(std::hypot(s.tip_side, s.tip_height), 0.95 * 0.03, 1e-12);
}

}  // namespace
}  // namespace billiard::params
