// A session of the table simulator as its command line starts it: the options of
// build/bin/table_sim_node (and of `billiard loop`, which runs the three nodes in one process),
// the session run over LCM, and its summary as one JSON object (session_summary.h).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <string>
#include <vector>

#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/physics/parameters.h"
#include "sim/table_sim_node/session_summary.h"
#include "sim/table_sim_node/table_sim_node.h"

namespace billiard::table_sim_node {

// The frames the simulated camera renders.
inline constexpr int kCameraWidth = 1280, kCameraHeight = 720;

struct SessionCommandLine {
  std::string lcm_url;  // empty: $LCM_DEFAULT_URL, else LCM's default
  std::string params = params::kDefaultParameterSet;
  std::string plant_params;  // --plant-params: the table's own physics; empty: `params`
  std::string noise = "off";  // "on": the robot's execution noise, RobotExecutionNoise()
  // --plant-noise: the noise the robot executes with when it differs from the one the planner
  // is told of (a name or a JSON file, sim/params/execution_noise.h); empty: `noise`'s.
  std::string plant_noise;
  std::string robot = params::kDefaultRobot;  // --robot: the robot that plays the strokes
  bool realtime = false;
  std::vector<std::string> pots;  // --pot K:P, in order
  std::string players;            // --players A,B
  std::string spins = "natural";  // --spins: the shots' spin styles in turn
  TableSimOptions options;
};

// The robot's execution noise with --noise on: the built-in model params::kDefaultNoise
// (sim/params/noise/robot.json), the one the shot choice plans for.
ExecutionNoise RobotExecutionNoise();

// Adds the session's options to `app`, filling `line` when it parses.
void AddSessionOptions(CLI::App& app, SessionCommandLine* line);

// The options of a parsed command line; throws std::invalid_argument with a one-line reason when
// they do not make a session (non-positive counts or rates, fault probabilities above 1, a --pot
// that is not K:P with K a ball id, or one without --scene, --players that are not two names or
// without a game of two players). Eight-ball without --players is ours against ours.
TableSimOptions SessionOptions(const SessionCommandLine& line);

// The simulated overhead camera of `table`.
camera::CameraModel SessionCamera(const physics::TableParameters& table);

// Nodes that run in this process beside the simulator (`billiard loop`): made on the session's
// LCM before the simulator subscribes, their work returned as the simulator's RunAlongside work.
using InProcessNodes = std::function<std::function<bool()>(
    lcm::LCM& lcm, const physics::ModelParameters& params, const camera::CameraModel& camera)>;

// Runs the session of a parsed command line and prints its summary (SessionSummary) as one JSON
// object on stdout. Returns the exit status: 0; 1 when LCM fails or a node does not answer in
// time; 2 for options that make no session (the reason on stderr, prefixed by `name`; also a
// match's player the planner does not know); 3 when
// the estimator or the planner runs other physics or another version (the session refused); 130 when stopped by
// SIGINT or SIGTERM. With options.scene, the whole-table session (RunScene), its summary under
// "scene"; a scene that does not load or fit is exit 2.
int RunSessionCommand(const std::string& name, const SessionCommandLine& line,
                      const InProcessNodes& in_process = nullptr);

}  // namespace billiard::table_sim_node
