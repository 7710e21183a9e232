#include "tools/billiard/plot_command.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/physics/simulator.h"
#include "sim/table/table_simulation.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/scene_commands.h"
#include "plot/canvas.h"
#include "plot/table_picture.h"

namespace billiard::cli {

namespace {

struct PlotArgs {
  std::string scene;
  std::string plan;
  std::string out;
  double sample_dt = plot::kPathSampleDt;
};

plot::TablePicture ScenePicture(const std::string& path, double dt) {
  params::SceneFile scene;
  try {
    scene = params::LoadScene(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const physics::ModelParameters params = LoadParametersOption(scene.params);
  plot::TablePicture picture;
  std::vector<table::SceneBall> balls;
  try {
    picture.table = table::BuildTable(params::LoadTableSpec(scene.table));
    balls = params::LaunchedBalls(scene, params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(path + ": " + e.what());
  }
  table::TableSimulationOptions options;
  options.five_dof = SceneMotionModel("auto", 0.0, params);
  std::unique_ptr<table::TableSimulation> sim;
  try {
    sim = std::make_unique<table::TableSimulation>(picture.table, params, balls, options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(path + ": " + e.what());
  }
  sim->Run();
  picture.ball_radius = params.ball.radius;
  plot::AddSimulation(*sim, dt, &picture);
  const auto cue = scene.cues.find(0);
  if (cue != scene.cues.end()) picture.cue = cue->second;
  std::ostringstream title;
  title << path << ": " << picture.table.name << ", " << params.name << ", "
        << sim->events().size() << " events, " << sim->time() << " s";
  picture.title = title.str();
  return picture;
}

// `billiard plan --json`'s object, a plan that was made ("status": "ok").
plot::TablePicture PlanPicture(const std::string& path, double dt) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read plan file '" + path + "'");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  const auto numbers = [&](const char* key, std::size_t n) {
    if (!j.is_object() || !j.contains(key) || !j[key].is_array() || j[key].size() != n) {
      throw UsageError(path + ": not a plan of `billiard plan --json` (" + key + " must be " +
                       std::to_string(n) + " numbers)");
    }
    std::vector<double> v;
    for (const auto& x : j[key]) {
      if (!x.is_number()) throw UsageError(path + ": " + key + " must be numbers");
      v.push_back(x.get<double>());
    }
    return v;
  };
  const auto from = numbers("from", 2), to = numbers("to", 2), v0 = numbers("v0", 2),
             w0 = numbers("w0", 3);
  if (j.value("status", "") != "ok") {
    throw UsageError(path + ": the plan was refused (" + j.value("status", "no status") +
                     "): it has no path to draw");
  }
  if (!j.contains("arrival_time") || !j["arrival_time"].is_number()) {
    throw UsageError(path + ": arrival_time must be a number");
  }
  const physics::ModelParameters params =
      LoadParametersOption(j.value("params_file", j.value("params", std::string("pool"))));
  plot::TablePicture picture;
  table::TableSpec spec;  // the parameter set's table: the rectangle a plan keeps to
  spec.name = params.name + " table";
  spec.length = params.table.length;
  spec.width = params.table.width;
  spec.cushion_height = params.ball.radius;
  picture.table = table::BuildTable(spec);
  picture.ball_radius = params.ball.radius;
  const physics::BallState initial =
      physics::MakeBallState(from[0], from[1], v0[0], v0[1], w0[0], w0[1], w0[2]);
  const double arrival = j["arrival_time"].get<double>();
  physics::SimulationResult run;
  try {
    run = physics::Simulate(params, initial, arrival);
  } catch (const std::exception& e) {
    throw UsageError(path + ": " + e.what());
  }
  plot::PictureBall ball;
  ball.start = initial;
  ball.path =
      plot::SampledPath(arrival, dt, {}, [&](double t) -> Eigen::Vector2d {
    return run.trajectory->At(t).head<2>();
  });
  picture.balls.push_back(ball);
  picture.target = Eigen::Vector2d(to[0], to[1]);
  if (j.contains("cue") && j["cue"].is_object()) {
    const nlohmann::json& c = j["cue"];
    picture.cue = physics::CueStroke{c.value("speed", 0.0), c.value("heading", 0.0),
                                     c.value("tip_side", 0.0), c.value("tip_height", 0.0),
                                     c.value("elevation", 0.0)};
  }
  std::ostringstream title;
  title << path << ": plan from (" << from[0] << ", " << from[1] << ") to (" << to[0] << ", "
        << to[1] << "), " << params.name << ", arrives at " << arrival << " s";
  picture.title = title.str();
  return picture;
}

void Run(const PlotArgs& args) {
  if (args.scene.empty() == args.plan.empty()) {
    throw UsageError("give one of --scene S.json and --plan P.json");
  }
  if (plot::FormatOf(args.out).empty()) {
    throw UsageError("--out '" + args.out + "': a picture is a .png or an .svg file");
  }
  if (!(args.sample_dt > 0.0 && std::isfinite(args.sample_dt))) {
    throw UsageError("--sample-dt must be a positive number of seconds");
  }
  // Said before the simulation: an output that cannot be made is a usage error. The file the
  // check makes is removed again, so that a refusal below leaves nothing behind.
  const bool existed = std::filesystem::exists(args.out);
  if (!std::ofstream(args.out, std::ios::app)) {
    throw UsageError("--out: cannot write '" + args.out + "'");
  }
  if (!existed) std::filesystem::remove(args.out);
  const plot::TablePicture picture = args.scene.empty() ? PlanPicture(args.plan, args.sample_dt)
                                                        : ScenePicture(args.scene, args.sample_dt);
  try {
    plot::DrawTable(picture, args.out);
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
  std::cerr << "plot: wrote " << args.out << " (" << picture.balls.size() << " balls, "
            << picture.events.size() << " events)\n";
}

}  // namespace

void AddPlotCommand(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw a scene simulated to rest, or a plan, as a PNG or SVG picture of the table: every "
      "ball's path, the events marked, the launch and spin shown");
  cmd->add_option("--scene", args->scene, "A scene file (as simulate --scene reads)");
  cmd->add_option("--plan", args->plan, "A plan (the JSON of `billiard plan --json`)");
  cmd->add_option("--out", args->out, "The picture: FILE.png or FILE.svg")->required();
  cmd->add_option("--sample-dt", args->sample_dt, "Time between the paths' points [s]")
      ->capture_default_str();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
