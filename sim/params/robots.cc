#include "sim/params/robots.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "sim/params/execution_noise.h"
#include "sim/params/strict_json.h"

namespace billiard::params {

namespace internal {
const std::vector<std::pair<std::string, std::string>>& BuiltinRobotJson();
}

namespace {

constexpr double kDegree = M_PI / 180.0;

// A {"min", "max"} object.
cue::Range ReadRange(const nlohmann::json& j, const char* key, const std::string& origin) {
  cue::Range range;
  internal::ReadSection(j.at(key), key, {{"min", &range.min}, {"max", &range.max}}, origin);
  return range;
}

std::optional<cue::Gantry> ReadGantry(const nlohmann::json& j, const std::string& origin) {
  if (!j.contains("gantry")) return std::nullopt;
  cue::Gantry gantry;
  internal::ReadSection(j.at("gantry"), "gantry",
                        {{"overhang", &gantry.overhang}, {"clearance", &gantry.clearance}}, origin);
  return gantry;
}

std::optional<cue::Arm> ReadArm(const nlohmann::json& j, const std::string& origin) {
  if (!j.contains("arm")) return std::nullopt;
  cue::Arm arm;
  internal::ReadSection(j.at("arm"), "arm",
                        {{"base_x", &arm.base.x()},
                         {"base_y", &arm.base.y()},
                         {"base_z", &arm.base.z()},
                         {"reach", &arm.reach}},
                        origin);
  return arm;
}

// The noise named by the robot, as LoadNoise reads it from anywhere: a built-in name as it is,
// a relative path joined to the robot file's folder. Refused when it does not load.
std::string ReadNoise(const nlohmann::json& j, const std::string& origin,
                      const std::string& folder) {
  if (!j.contains("noise")) {
    throw std::invalid_argument(origin + ": missing noise (a noise model's name or file)");
  }
  std::string noise = internal::ReadText(j, "noise", "", origin);
  const std::vector<std::string> builtin = BuiltinNoiseNames();
  const bool named = std::find(builtin.begin(), builtin.end(), noise) != builtin.end();
  if (!named && !folder.empty() && std::filesystem::path(noise).is_relative()) {
    noise = (std::filesystem::path(folder) / noise).string();
  }
  try {
    LoadNoise(noise);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(origin + ": noise: " + e.what());
  }
  return noise;
}

}  // namespace

std::vector<std::string> RobotNames() {
  std::vector<std::string> names;
  for (const auto& [name, json] : internal::BuiltinRobotJson()) names.push_back(name);
  return names;
}

cue::Robot ParseRobot(const std::string& json_text, const std::string& origin,
                      const std::string& folder) {
  const nlohmann::json j = internal::ParseObject(json_text, origin, "a robot");
  cue::Robot robot;
  internal::ReadSection(
      j, "", {{"bridge", &robot.bridge}, {"max_tip_offset", &robot.max_tip_offset}}, origin,
      {"name", "source", "cue", "elevation_deg", "speed_mps", "gantry", "arm", "noise"});
  for (const char* key : {"cue", "elevation_deg", "speed_mps"}) {
    if (!j.contains(key)) throw std::invalid_argument(origin + ": missing object " + key);
  }
  internal::ReadSection(j.at("cue"), "cue",
                        {{"length", &robot.cue.length},
                         {"tip_radius", &robot.cue.tip_radius},
                         {"butt_radius", &robot.cue.butt_radius}},
                        origin);
  const cue::Range elevation_deg = ReadRange(j, "elevation_deg", origin);
  robot.elevation = {elevation_deg.min * kDegree, elevation_deg.max * kDegree};
  robot.speed = ReadRange(j, "speed_mps", origin);
  robot.gantry = ReadGantry(j, origin);
  robot.arm = ReadArm(j, origin);
  robot.name = internal::ReadText(j, "name", origin, origin);
  robot.source = internal::ReadText(j, "source", "", origin);
  try {
    cue::ValidateRobot(robot);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(origin + ": " + e.what());
  }
  robot.noise = ReadNoise(j, origin, folder);
  return robot;
}

cue::Robot LoadRobot(const std::string& name_or_path) {
  bool from_file = false;
  const std::string text = internal::BuiltinOrFileText(internal::BuiltinRobotJson(), name_or_path,
                                                       "robot", "robot", &from_file);
  const std::string folder =
      from_file ? std::filesystem::path(name_or_path).parent_path().string() : "";
  return ParseRobot(text, name_or_path, folder);
}

}  // namespace billiard::params
