#include "tools/billiard/scene_commands.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bench/scene_benchmark.h"
#include "planner/choice/monte_carlo.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/params/table_specs.h"
#include "sim/table/rack.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The accuracy of --model auto: --accuracy, or the scene's default.
double SceneAccuracy(double accuracy) {
  return accuracy > 0.0 ? accuracy : model_choice::kSceneAccuracy;
}

table::CushionModel CushionModelOption(const std::string& name) {
  const auto model = table::ParseCushionModel(name);
  if (!model) {
    throw UsageError("--cushion-model: unknown model '" + name + "' (mathavan-2010, han-2005)");
  }
  return *model;
}

// The models a scene ran with, in words, for the readable summary.
std::string ModelsInWords(const SceneSimulationArgs& args, const physics::ModelParameters& params,
                          bool struck) {
  std::ostringstream out;
  out << "models: motion ";
  if (args.model == "closed-form") {
    out << "closed form for every ball (Jaroukh 2019)";
  } else if (args.model == "approx") {
    out << "approximate 5-DOF model (Kudra et al. 2016) for every moving ball";
  } else {
    const physics::SimulationOptions method =
        model_choice::TableMotionMethod(params, SceneAccuracy(args.accuracy));
    out << "auto: closed form while a ball rolls, 5-DOF " << physics::ModelName(method.model)
        << "/" << physics::IntegratorName(method.integrator) << " (tol " << method.tolerance
        << " m) while it slides or spins (accuracy "
        << SceneAccuracy(args.accuracy) << " m)";
  }
  out << "; cushion " << args.cushion_model
      << "; ball-ball restitution with Alciatore's throw friction (TP A.14)";
  if (struck) out << "; cue strike with squirt (Alciatore TP A.30, A.31)";
  return out.str();
}

// `simulate --scene` without --json: where each ball started and ended, its cushions, which
// pocket it dropped into and when; on stderr.
void PrintSceneTable(const table::TableSimulation& sim,
                     const std::vector<table::SceneBall>& start) {
  std::ostringstream out;
  out << std::fixed;
  out << "ball    start X, Y [m]      end X, Y [m]  speed m/s  cushions  pocketed\n";
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    const physics::BallState s = sim.State(i);
    int cushions = 0;
    double dropped = -1.0;
    for (const table::TableEvent& e : sim.events()) {
      if (e.ball != sim.id(i)) continue;
      cushions += e.type == table::EventType::kBallCushion || e.type == table::EventType::kBallJaw;
      if (e.type == table::EventType::kBallPocket) dropped = e.time;
    }
    const physics::BallState& s0 =
        std::find_if(start.begin(), start.end(), [&](const table::SceneBall& b) {
          return b.id == sim.id(i);
        })->state;
    out << std::setw(4) << sim.id(i) << "  " << std::setprecision(3) << std::setw(8)
        << s0[physics::kX] << ", " << std::setw(6) << s0[physics::kY] << "  " << std::setw(8)
        << s[physics::kX] << ", " << std::setw(6) << s[physics::kY] << "  " << std::setw(9)
        << std::hypot(s[physics::kVx], s[physics::kVy]) << "  " << std::setw(8) << cushions
        << "  ";
    if (sim.pocket(i)) {
      out << *sim.pocket(i) << " at " << std::setprecision(2) << dropped << " s";
    } else {
      out << "-";
    }
    out << "\n";
  }
  std::cerr << out.str();
}

// The table at the end of `sim` as a scene of `scene`'s table and parameters: the balls left on
// it, a ball resting past a pocket's mouth dropped into that pocket (choice::DropHangingBalls: a
// real one would, and no tool is asked about a ball hanging there), said on stderr.
params::SceneFile SceneAtEnd(const table::TableGeometry& geometry, const table::TableSimulation& sim,
                             const params::SceneFile& scene) {
  choice::StrokeResult end;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    if (!sim.pocket(i)) end.rest.push_back({sim.id(i), sim.State(i)});
  }
  choice::DropHangingBalls(geometry, &end);
  for (const auto& [id, pocket] : end.pocketed) {
    std::cerr << "simulate: ball " << id << " rests over " << pocket << "'s mouth: dropped\n";
  }
  if (end.scratch) std::cerr << "simulate: the cue ball rests over a pocket's mouth: dropped\n";
  params::SceneFile out;
  out.table = scene.table;
  out.params = scene.params;
  out.balls = end.rest;
  return out;
}

}  // namespace

void WriteScene(const params::SceneFile& scene, const std::string& path, const std::string& option) {
  std::ofstream out(path);
  if (!(out << params::SceneJson(scene) << "\n")) {
    throw UsageError(option + ": cannot write '" + path + "'");
  }
}

table::TableGeometry LoadTableOption(const std::string& name_or_path) {
  try {
    return table::BuildTable(params::LoadTableSpec(name_or_path));
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

nlohmann::json EventJson(const table::TableEvent& e) {
  nlohmann::json j = {{"t", e.time}, {"type", table::EventTypeName(e.type)}};
  j["balls"] = e.other >= 0 ? std::vector<int>{e.ball, e.other} : std::vector<int>{e.ball};
  switch (e.type) {
    case table::EventType::kTransition:
      j["from"] = table::PhaseName(e.from);
      j["to"] = table::PhaseName(e.to);
      break;
    case table::EventType::kBallPocket:
      j["pocket"] = e.pocket;
      break;
    case table::EventType::kBallCushion:
    case table::EventType::kBallJaw:
      j["cushion"] = e.cushion;
      j["impulse"] = e.impulse;
      break;
    case table::EventType::kBallBall:
      j["impulse"] = e.impulse;
      break;
    case table::EventType::kBallPush:
      if (e.cushion >= 0) j["cushion"] = e.cushion;
      break;
  }
  return j;
}

decltype(table::TableSimulationOptions::five_dof) SceneMotionModel(
    const std::string& model, double accuracy, const physics::ModelParameters& params) {
  using Choice = std::optional<physics::SimulationOptions>;
  if (model == "closed-form") return nullptr;
  if (model == "approx") return [](const physics::BallState&) -> Choice { return {{}}; };
  if (model != "auto") {
    throw UsageError("--model: unknown model '" + model +
                     "' for a scene (auto, closed-form, approx)");
  }
  if (accuracy < 0.0 || !std::isfinite(accuracy)) {
    throw UsageError("--accuracy must be a positive number of metres");
  }
  return model_choice::TableMotion(params, SceneAccuracy(accuracy));
}

void SimulateScene(const SceneSimulationArgs& args) {
  if (args.t_end && !(std::isfinite(*args.t_end) && *args.t_end >= 0.0)) {
    throw UsageError("--t-end must be a finite number >= 0");
  }
  if (!(args.sample_dt > 0.0) || !std::isfinite(args.sample_dt)) {
    throw UsageError("--sample-dt must be a positive number of seconds");
  }
  params::SceneFile scene;
  try {
    scene = params::LoadScene(args.scene_path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (args.cue) scene.cues[0] = *args.cue;
  const physics::ModelParameters params = LoadParametersOption(scene.params);
  const table::TableGeometry geometry = LoadTableOption(scene.table);
  std::vector<table::SceneBall> balls;
  try {
    balls = params::LaunchedBalls(scene, params);
  } catch (const std::invalid_argument& e) {
    throw UsageError(args.scene_path + ": " + e.what());
  }
  table::TableSimulationOptions options;
  options.cushion_model = CushionModelOption(args.cushion_model);
  options.five_dof = SceneMotionModel(args.model, args.accuracy, params);

  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<table::TableSimulation> sim;
  try {
    sim = std::make_unique<table::TableSimulation>(geometry, params, balls, options);
  } catch (const std::invalid_argument& e) {
    throw UsageError(args.scene_path + ": " + e.what());
  }
  sim->Run(args.t_end.value_or(std::numeric_limits<double>::infinity()));
  const double wall_us =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();

  if (!args.trajectory_path.empty()) {
    WriteTrajectoryCsv(
        args.trajectory_path, sim->time(), args.sample_dt, static_cast<int>(sim->ball_count()),
        [&](double t, int k) { return sim->StateAt(k, t); }, [&](int k) { return sim->id(k); });
  }
  if (!args.scene_out.empty()) WriteScene(SceneAtEnd(geometry, *sim, scene), args.scene_out, "--scene-out");
  nlohmann::json j;
  j["table"] = geometry.name;
  DescribeParameters(params, &j);
  j["model"] = args.model;
  if (args.model == "auto") j["accuracy_m"] = SceneAccuracy(args.accuracy);
  j["cushion_model"] = args.cushion_model;
  j["t"] = sim->time();
  j["balls"] = nlohmann::json::array();
  int pocketed = 0;
  for (std::size_t i = 0; i < sim->ball_count(); ++i) {
    const physics::BallState s = sim->State(i);
    nlohmann::json ball = {{"id", sim->id(i)},
                           {"state", std::vector<double>(s.data(), s.data() + 7)}};
    ball["pocketed"] = sim->pocket(i) ? nlohmann::json(*sim->pocket(i)) : nlohmann::json();
    pocketed += sim->pocket(i) ? 1 : 0;
    j["balls"].push_back(ball);
  }
  j["events"] = nlohmann::json::array();
  for (const table::TableEvent& e : sim->events()) j["events"].push_back(EventJson(e));
  j["at_rest"] = sim->AtRest();
  j["wall_us"] = wall_us;
  if (args.json) {
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << geometry.name << ", " << params::ParameterSetLabel(params)
              << " parameters: " << sim->ball_count() << " balls, " << sim->events().size()
              << " events to t = " << sim->time() << " s, " << pocketed << " pocketed"
              << (sim->AtRest() ? ", all at rest" : "") << ", " << wall_us << " us\n"
              << ModelsInWords(args, params, !scene.cues.empty()) << "\n";
    PrintSceneTable(*sim, balls);
  }
}

void AddRackCommand(CLI::App& app) {
  struct Args {
    std::string kind;
    std::string table;
    std::string params = params::kDefaultParameterSet;
    std::uint64_t seed = 0;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "rack", "The balls of a rack at rest as a scene (JSON on stdout, for simulate --scene)");
  cmd->add_option("kind", args->kind, "eight-ball | nine-ball | snooker | three-cushion")
      ->required();
  cmd->add_option("--table", args->table,
                  std::string("Table specification (default: ") + params::kDefaultTable +
                      "; snooker-12ft for snooker, "
                      "carom-10ft for three-cushion)");
  cmd->add_option("--params", args->params,
                  "Parameter set (default: pool; snooker and carom for their racks)");
  cmd->add_option("--seed", args->seed, "Seed of the rack's order and gaps")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", "The scene as JSON on stdout (the only output; accepted for symmetry)");
  cmd->callback([args, cmd] {
    table::RackKind kind;
    try {
      kind = table::ParseRackKind(args->kind);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    const bool params_given = cmd->count("--params") > 0;
    params::SceneFile scene;
    scene.table = args->table;
    scene.params = args->params;
    if (scene.table.empty()) {
      scene.table = kind == table::RackKind::kSnooker        ? "snooker-12ft"
                    : kind == table::RackKind::kThreeCushion ? "carom-10ft"
                                                             : params::kDefaultTable;
    }
    if (!params_given && kind == table::RackKind::kSnooker) scene.params = "snooker";
    if (!params_given && kind == table::RackKind::kThreeCushion) scene.params = "carom";
    const physics::ModelParameters params = LoadParametersOption(scene.params);
    const table::TableGeometry geometry = LoadTableOption(scene.table);
    try {
      scene.balls = table::Rack(kind, geometry, params.ball.radius, args->seed);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    std::cout << params::SceneJson(scene) << std::endl;
  });
}

void AddBenchScenesCommand(CLI::App& app) {
  struct Args {
    bench::SceneBenchmarkOptions options;
    std::string table = params::kDefaultTable;
    std::string params = params::kDefaultParameterSet;
    std::string out;
    std::string cushion_model;  // "" with model "": every run below
    std::string model;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("bench-scenes",
                         "Simulate seeded 16-ball breaks until rest, timed on one core; events per "
                         "break and cost per event (JSON on stdout, a report with --out)");
  cmd->add_option("--breaks", args->options.breaks, "Number of seeded breaks")
      ->capture_default_str();
  cmd->add_option("--seed", args->options.seed, "Seed of the first break")->capture_default_str();
  cmd->add_option("--speed", args->options.speed, "The cue ball's launch speed [m/s]")
      ->capture_default_str();
  cmd->add_option("--repeats", args->options.repeats, "Timed runs per break (the fastest kept)")
      ->capture_default_str();
  cmd->add_option("--table", args->table, "Table specification")->capture_default_str();
  cmd->add_option("--params", args->params, "Parameter set")->capture_default_str();
  cmd->add_option("--cushion-model", args->cushion_model,
                  "mathavan-2010 | han-2005 (without it and --model: closed form with each, and "
                  "auto with mathavan-2010, one after the other)");
  cmd->add_option("--model", args->model, "closed-form | approx | auto (5-DOF where needed)");
  cmd->add_option("--out", args->out, "Write scenes_report.md into this directory");
  cmd->callback([args] {
    if (args->options.breaks < 1) throw UsageError("--breaks must be at least 1");
    if (!(args->options.speed > 0.0 && std::isfinite(args->options.speed))) {
      throw UsageError("--speed must be a positive number of m/s");
    }
    if (!args->out.empty()) RequireWritableDirectory(args->out, "--out");
    const physics::ModelParameters params = LoadParametersOption(args->params);
    const table::TableGeometry geometry = LoadTableOption(args->table);
    // The runs: both cushion models in closed form, and the 5-DOF model where it is needed.
    std::vector<std::pair<std::string, table::CushionModel>> runs = {
        {"closed-form", table::CushionModel::kMathavan2010},
        {"closed-form", table::CushionModel::kHan2005},
        {"auto", table::CushionModel::kMathavan2010}};
    if (!args->cushion_model.empty() || !args->model.empty()) {
      runs = {{args->model.empty() ? "closed-form" : args->model,
               args->cushion_model.empty() ? table::CushionModel::kMathavan2010
                                           : CushionModelOption(args->cushion_model)}};
    }
    args->options.progress = [](const std::string& line) { std::cerr << line << "\n"; };
    std::vector<bench::SceneBenchmarkResult> results;
    nlohmann::json summary = nlohmann::json::array();
    for (const auto& [motion, cushion] : runs) {
      args->options.motion_model = motion;
      args->options.simulation.five_dof = SceneMotionModel(motion, 0.0, params);
      args->options.simulation.cushion_model = cushion;
      results.push_back(bench::RunSceneBenchmark(geometry, params, args->options));
      summary.push_back(bench::SceneSummaryJson(results.back()));
    }
    if (!args->out.empty()) {
      bench::WriteSceneReport(results, args->out);
      std::cerr << "bench-scenes: wrote " << args->out << "/scenes_report.md\n";
    }
    std::cout << (summary.size() == 1 ? summary[0] : summary).dump() << std::endl;
  });
}

}  // namespace billiard::cli
