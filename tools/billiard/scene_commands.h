// The table's subcommands: `billiard simulate --scene` (every ball, event by event), `billiard
// rack` (the balls of a rack as a scene) and `billiard bench-scenes` (seeded breaks, timed).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "sim/params/scene_file.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/table/table_simulation.h"

namespace billiard::cli {

struct SceneSimulationArgs {
  std::string scene_path;
  std::optional<physics::CueStroke> cue;  // --cue: the stroke of the cue ball (id 0)
  std::optional<double> t_end;  // none: until every ball rests or is pocketed
  std::string model;            // auto | closed-form | approx
  double accuracy = 0.0;        // auto: the endpoint error allowed a ball's motion (0: 5 mm)
  std::string cushion_model;    // mathavan-2010 | han-2005
  std::string trajectory_path;
  double sample_dt = 1e-3;
  std::string scene_out;  // the table at the end, as a scene
  bool json = false;
};

// `billiard simulate --scene SCENE.json`: the scene's JSON result on stdout (with --json) or a
// summary on stderr.
void SimulateScene(const SceneSimulationArgs& args);

// The motion model of every new motion of a ball for --model closed-form | approx | auto (the
// cheapest whose measured error on that kind of motion, sim/model_choice/, is within `accuracy`
// metres); UsageError for another name.
decltype(table::TableSimulationOptions::five_dof) SceneMotionModel(
    const std::string& model, double accuracy, const physics::ModelParameters& params);

// `scene` written as a scene file at `path` (the pure scene every --scene reads), or a
// UsageError naming `option`.
void WriteScene(const params::SceneFile& scene, const std::string& path, const std::string& option);

// The table of a scene's "table" (a name or a file); UsageError with the reason.
table::TableGeometry LoadTableOption(const std::string& name_or_path);

// An event as `simulate --scene --json` prints it: {"t", "type", "balls", and the kind's own
// keys}.
nlohmann::json EventJson(const table::TableEvent& e);

void AddRackCommand(CLI::App& app);
void AddBenchScenesCommand(CLI::App& app);

}  // namespace billiard::cli
