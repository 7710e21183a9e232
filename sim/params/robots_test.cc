#include "sim/params/robots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"

namespace billiard::params {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kInch = 0.0254;

TEST(RobotsTest, BuiltInRobotsLoad) {
  std::vector<std::string> names = RobotNames();
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"gantry", "player"}));
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const cue::Robot robot = LoadRobot(name);
    EXPECT_EQ(robot.name, name);
    EXPECT_FALSE(robot.source.empty()) << "a robot says where its numbers come from";
    EXPECT_NO_THROW(cue::ValidateRobot(robot));
    EXPECT_NO_THROW(LoadNoise(robot.noise));
  }
}

// The default robot is the one the planner and the table simulator assumed before robots were
// data: the planner's elevations (up to 60 degrees, where a cue must rise that far), the
// parameter sets' tip offset and speed limits, the table simulator's noise; and its body never
// binds on a stroke of those (level, the tip within the limit of the centre, on any built-in
// ball).
TEST(RobotsTest, TheGantryIsTodaysRobot) {
  EXPECT_STREQ(kDefaultRobot, "gantry");
  const cue::Robot gantry = LoadRobot(kDefaultRobot);
  EXPECT_EQ(gantry.elevation.min, 0.0);
  EXPECT_DOUBLE_EQ(gantry.elevation.max, 60 * kDegree);
  EXPECT_EQ(gantry.noise, kDefaultNoise);
  ASSERT_TRUE(gantry.gantry.has_value());
  EXPECT_FALSE(gantry.arm.has_value());
  for (const std::string& set : BuiltinParameterSetNames()) {
    SCOPED_TRACE(set);
    const physics::ModelParameters p = LoadParameters(set);
    EXPECT_EQ(gantry.max_tip_offset, p.cue.max_tip_offset);
    EXPECT_EQ(gantry.speed.max, p.cue.max_speed);
    const double r = p.ball.radius;
    EXPECT_GT(r * (1 - gantry.max_tip_offset), gantry.gantry->clearance)
        << "the carriage stays above its clearance on a level stroke";
    EXPECT_GT(gantry.gantry->overhang, gantry.cue.length + 2 * r) << "no butt reaches the frame";
  }
}

// The player: a standard 58 in cue (1.47 m) with a 13 mm tip (the WPA's at most 14) and a butt
// of 29-31 mm; FastFiz's strokes (elevation to 70 degrees, speed to 10 m/s); no body; the
// computational pool tournaments' noise.
TEST(RobotsTest, ThePlayerIsComputationalPools) {
  const cue::Robot player = LoadRobot("player");
  EXPECT_NEAR(player.cue.length, 58 * kInch, 0.005);
  EXPECT_DOUBLE_EQ(2 * player.cue.tip_radius, 0.013);
  EXPECT_GE(2 * player.cue.butt_radius, 0.029);
  EXPECT_LE(2 * player.cue.butt_radius, 0.031);
  EXPECT_DOUBLE_EQ(player.elevation.max, 70 * kDegree);
  EXPECT_EQ(player.speed.max, 10.0);
  EXPECT_FALSE(player.gantry || player.arm);
  EXPECT_EQ(player.noise, "computational-pool");
}

const std::string kValid = R"({"name": "r", "source": "test",
  "cue": {"length": 1.0, "tip_radius": 0.0065, "butt_radius": 0.012},
  "bridge": 0.2,
  "elevation_deg": {"min": 0, "max": 60},
  "max_tip_offset": 0.5,
  "speed_mps": {"min": 0, "max": 8},
  "gantry": {"overhang": 0.5, "clearance": 0.01},
  "noise": "robot"})";

// kValid with the first `from` replaced by `to`.
std::string With(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

void ExpectRefused(const std::string& json, const std::string& message) {
  try {
    ParseRobot(json, "r.json");
    ADD_FAILURE() << "accepted; expected: " << message;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
  }
}

TEST(RobotsTest, ReadsEveryNumberInSiUnits) {
  const cue::Robot robot = ParseRobot(kValid, "r.json");
  EXPECT_EQ(robot.name, "r");
  EXPECT_EQ(robot.cue.length, 1.0);
  EXPECT_EQ(robot.cue.tip_radius, 0.0065);
  EXPECT_EQ(robot.cue.butt_radius, 0.012);
  EXPECT_EQ(robot.bridge, 0.2);
  EXPECT_DOUBLE_EQ(robot.elevation.max, 60 * kDegree);
  EXPECT_EQ(robot.speed.max, 8.0);
  ASSERT_TRUE(robot.gantry.has_value());
  EXPECT_EQ(robot.gantry->overhang, 0.5);
  EXPECT_EQ(robot.gantry->clearance, 0.01);
  const cue::Robot arm =
      ParseRobot(With(R"("gantry": {"overhang": 0.5, "clearance": 0.01})",
                      R"("arm": {"base_x": 1.2, "base_y": -0.4, "base_z": 0.6, "reach": 1.1})"),
                 "a.json");
  ASSERT_TRUE(arm.arm.has_value());
  EXPECT_EQ(arm.arm->base, Eigen::Vector3d(1.2, -0.4, 0.6));
  EXPECT_EQ(arm.arm->reach, 1.1);
  EXPECT_EQ(ParseRobot(With(R"("name": "r", )", ""), "r.json").name, "r.json");
}

TEST(RobotsTest, RefusesEveryBadField) {
  ExpectRefused(With(R"("bridge")", R"("bridje")"), "r.json: unknown key bridje");
  ExpectRefused(With(R"("length")", R"("lenght")"), "r.json: unknown key cue.lenght");
  ExpectRefused(With(R"("tip_radius": 0.0065, )", ""), "r.json: missing number cue.tip_radius");
  ExpectRefused(With(R"("max_tip_offset": 0.5)", R"("max_tip_offset": "half")"),
                "r.json: max_tip_offset must be a number, not string");
  ExpectRefused(With(R"("speed_mps": {"min": 0, "max": 8},)", ""),
                "r.json: missing object speed_mps");
  ExpectRefused(With(R"("elevation_deg": {"min": 0, "max": 60})", R"("elevation_deg": 60)"),
                "r.json: \"elevation_deg\" must be an object, not number");
  ExpectRefused(With(R"("max": 60)", R"("max": 60, "step": 1)"),
                "r.json: unknown key elevation_deg.step");
  ExpectRefused(With(R"("clearance": 0.01)", R"("clearence": 0.01)"),
                "r.json: unknown key gantry.clearence");
  ExpectRefused(With(R"("length": 1.0)", R"("length": -1.0)"),
                "r.json: cue.length must be positive");
  ExpectRefused(With(R"("butt_radius": 0.012)", R"("butt_radius": 0.005)"),
                "r.json: cue.butt_radius must be at least cue.tip_radius");
  ExpectRefused(With(R"("bridge": 0.2)", R"("bridge": 1.2)"),
                "r.json: bridge must be in [0, cue.length]");
  ExpectRefused(With(R"("max": 60)", R"("max": 95)"), "r.json: elevation_deg.max must be below 90");
  ExpectRefused(With(R"("min": 0, "max": 60)", R"("min": 30, "max": 20)"),
                "r.json: elevation_deg.min must be in [0, elevation_deg.max]");
  ExpectRefused(With(R"("max_tip_offset": 0.5)", R"("max_tip_offset": 1.5)"),
                "r.json: max_tip_offset must be in (0, 1)");
  ExpectRefused(With(R"("min": 0, "max": 8)", R"("min": 0, "max": 0)"),
                "r.json: speed_mps.max must be positive");
  ExpectRefused(With(R"("overhang": 0.5)", R"("overhang": -0.5)"),
                "r.json: gantry.overhang must be >= 0");
  ExpectRefused(
      With(R"("noise": "robot")",
           R"("noise": "robot", "arm": {"base_x": 0, "base_y": 0, "base_z": 0, "reach": 1})"),
      "r.json: a robot is a gantry or an arm, not both");
  ExpectRefused(With(R"("noise": "robot")", R"("noise": "steady-hand")"),
                "r.json: noise: unknown noise model 'steady-hand'");
  ExpectRefused(With(R"("noise": "robot")", R"("noise": 0.1)"),
                "r.json: noise must be a string, not number");
  ExpectRefused(With(R"(,
  "noise": "robot")",
                     ""),
                "r.json: missing noise");
  ExpectRefused("[1]", "r.json: a robot is a JSON object");
  ExpectRefused("{", "r.json: not valid JSON");
}

// A robot file names its noise file beside it; LoadRobot gives that file's path.
TEST(RobotsTest, LoadsAFileWithItsNoiseBesideIt) {
  const std::filesystem::path folder =
      std::filesystem::path(::testing::TempDir()) / "robots_test_folder";
  std::filesystem::create_directories(folder);
  {
    std::ofstream(folder / "measured.json") << R"({"name": "measured", "speed_fraction": 0.02,
      "speed_mps": 0, "heading_deg": 0.2, "tip_mm": 0.3, "elevation_deg": 0})";
    std::ofstream(folder / "mine.json")
        << With(R"("noise": "robot")", R"("noise": "measured.json")");
  }
  const cue::Robot robot = LoadRobot((folder / "mine.json").string());
  EXPECT_EQ(robot.name, "r");
  EXPECT_EQ(std::filesystem::path(robot.noise), folder / "measured.json");
  EXPECT_EQ(LoadNoise(robot.noise).name, "measured");
  std::filesystem::remove_all(folder);
  try {
    LoadRobot("crane");
    ADD_FAILURE() << "accepted an unknown robot";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown robot 'crane' (not a built-in robot: gantry, player; not a readable file)");
  }
}

}  // namespace
}  // namespace billiard::params
