// The table's subcommands: `billiard simulate --scene` (every ball, event by event), `billiard
// rack` (the balls of a rack as a scene) and `billiard bench-scenes` (seeded breaks, timed).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace billiard::cli {

struct SceneSimulationArgs {
  std::string scene_path;
  std::optional<double> t_end;  // none: until every ball rests or is pocketed
  std::string model;            // auto | closed-form
  std::string cushion_model;    // mathavan-2010 | han-2005
  std::string trajectory_path;
  double sample_dt = 1e-3;
  bool json = false;
};

// `billiard simulate --scene SCENE.json`: the scene's JSON result on stdout (with --json) or a
// summary on stderr.
void SimulateScene(const SceneSimulationArgs& args);

void AddRackCommand(CLI::App& app);
void AddBenchScenesCommand(CLI::App& app);

}  // namespace billiard::cli
