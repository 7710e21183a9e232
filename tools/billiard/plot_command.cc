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

#include "sim/cue/clearance.h"
#include "sim/cue/placed_cue.h"
#include "sim/cue/robot.h"
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
  std::string robot;  // empty: the plan's robot, else the default one
  double sample_dt = plot::kPathSampleDt;
};

// A plan's JSON as read: the object, or a usage error naming the file.
nlohmann::json ReadPlan(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read plan file '" + path + "'");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) throw UsageError(path + ": not a plan's JSON object");
  if (j.value("status", "") != "ok") {
    throw UsageError(path + ": the plan was refused (" + j.value("status", "no status") +
                     "): it has no path to draw");
  }
  return j;
}

// The plan's stroke ("cue", as `billiard plan` and `plan-pot` write it).
std::optional<physics::CueStroke> StrokeOf(const nlohmann::json& plan) {
  if (!plan.contains("cue") || !plan["cue"].is_object()) return std::nullopt;
  const nlohmann::json& c = plan["cue"];
  return physics::CueStroke{c.value("speed", 0.0), c.value("heading", 0.0), c.value("tip_side", 0.0),
                            c.value("tip_height", 0.0), c.value("elevation", 0.0)};
}

// The clearance the planner reported with the plan's stroke (cue.clearance), if it did.
std::optional<cue::CueClearance> ReportedClearance(const nlohmann::json& plan) {
  if (!plan.contains("cue") || !plan["cue"].contains("clearance")) return std::nullopt;
  const nlohmann::json& c = plan["cue"]["clearance"];
  if (!c.is_object() || !c.value("distance", nlohmann::json()).is_number()) return std::nullopt;
  cue::CueClearance reported;
  reported.clears = c.value("clears", false);
  reported.what = c.value("nearest", std::string());
  reported.ball = c.value("ball", -1);
  reported.nearest = reported.ball >= 0 ? cue::Obstacle::kBall : cue::Obstacle::kTable;
  reported.distance = c["distance"].get<double>();
  reported.along = c.value("along", 0.0);
  return reported;
}

// The robot's cue of `stroke` on the ball at `centre`, from above (plot/cue_outline.h): placed as
// the planner places it (sim/cue/placed_cue.h), the point `clearance.along` from its tip marked,
// and a ball that comes nearest joined to it.
plot::CueOutline RobotCue(const Eigen::Vector2d& centre, double radius, const physics::CueStroke& stroke,
                          const cue::Robot& robot, const std::optional<cue::CueClearance>& clearance,
                          const std::vector<table::SceneBall>& balls) {
  cue::PlacedCue placed;
  try {
    placed = cue::PlaceCue(centre, radius, stroke, robot.cue);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("the cue: ") + e.what());
  }
  plot::CueOutline outline;
  outline.tip = placed.tip.head<2>();
  outline.butt = placed.At(robot.cue.length).head<2>();
  outline.tip_radius = robot.cue.tip_radius;
  outline.butt_radius = robot.cue.butt_radius;
  outline.elevation = stroke.elevation;
  if (!clearance || !std::isfinite(clearance->distance)) return outline;
  outline.nearest = placed.At(clearance->along).head<2>();
  outline.nearest_what = clearance->what;
  outline.distance = clearance->distance;
  for (const table::SceneBall& b : balls) {
    if (clearance->nearest == cue::Obstacle::kBall && b.id == clearance->ball) {
      outline.obstacle = b.state.head<2>();
    }
  }
  return outline;
}

// The robot `--robot` names, else the plan's, else the default; none for "none".
std::optional<cue::Robot> PictureRobot(const PlotArgs& args, const nlohmann::json& plan) {
  const std::string name = !args.robot.empty() ? args.robot : plan.value("robot", std::string("gantry"));
  return LoadRobotOrNone(name);
}

// A picture, and the balls where they stood when the cue struck (what the cue must clear).
struct Drawing {
  plot::TablePicture picture;
  std::vector<table::SceneBall> balls;
};

// A scene simulated to rest; with `stroke`, ball 0 struck by it (a plan-pot plan on its scene).
Drawing ScenePicture(const std::string& path, double dt, const std::optional<physics::CueStroke>& stroke) {
  params::SceneFile scene;
  try {
    scene = params::LoadScene(path);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (stroke) scene.cues[0] = *stroke;
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
  return {picture, balls};
}

// `billiard plan --json`'s object `j`, read from `path`, a plan that was made.
Drawing PlanPicture(const std::string& path, const nlohmann::json& j, double dt) {
  const auto numbers = [&](const char* key, std::size_t n) {
    if (!j.contains(key) || !j[key].is_array() || j[key].size() != n) {
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
  picture.cue = StrokeOf(j);
  std::ostringstream title;
  title << path << ": plan from (" << from[0] << ", " << from[1] << ") to (" << to[0] << ", "
        << to[1] << "), " << params.name << ", arrives at " << arrival << " s";
  picture.title = title.str();
  table::SceneBall cue_ball;
  cue_ball.state = initial;
  return {picture, {cue_ball}};
}

// The picture's plain cue made the robot's: on a scene, its clearance found as the planner finds
// it (the same balls, table and robot); on a plan alone, the clearance the plan reports, when the
// robot drawn is the plan's.
void AddRobotCue(const PlotArgs& args, const nlohmann::json& plan, Drawing* d) {
  plot::TablePicture& pic = d->picture;
  const std::optional<cue::Robot> robot = PictureRobot(args, plan);
  if (!pic.cue || !robot) return;
  std::optional<cue::CueClearance> clearance;
  if (!args.scene.empty()) {
    try {
      clearance = cue::Clearance(pic.table, pic.ball_radius, d->balls, 0, *pic.cue, *robot);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("the cue: ") + e.what());
    }
  } else if (plan.value("robot", std::string()) == robot->name) {
    clearance = ReportedClearance(plan);
  }
  for (const table::SceneBall& b : d->balls) {
    if (b.id == 0) pic.robot_cue = RobotCue(b.state.head<2>(), pic.ball_radius, *pic.cue, *robot, clearance, d->balls);
  }
}

// What --scene and --plan ask to be drawn: a scene, a `plan` plan, or a `plan-pot` plan on its
// scene.
Drawing Picture(const PlotArgs& args, const nlohmann::json& plan) {
  const bool pot_plan = plan.contains("pocket");
  if (args.scene.empty()) {
    if (pot_plan) throw UsageError(args.plan + ": a plan of `plan-pot`: give its scene with --scene");
    return PlanPicture(args.plan, plan, args.sample_dt);
  }
  if (!args.plan.empty() && !pot_plan) {
    throw UsageError("--plan with --scene: a plan of `billiard plan-pot --json` (its ball and pocket)");
  }
  return ScenePicture(args.scene, args.sample_dt, args.plan.empty() ? std::nullopt : StrokeOf(plan));
}

void Run(const PlotArgs& args) {
  if (args.scene.empty() && args.plan.empty()) {
    throw UsageError("give --scene S.json, --plan P.json, or both (a plan-pot plan on its scene)");
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
  const nlohmann::json plan = args.plan.empty() ? nlohmann::json::object() : ReadPlan(args.plan);
  Drawing drawing = Picture(args, plan);
  AddRobotCue(args, plan, &drawing);
  const plot::TablePicture& picture = drawing.picture;
  try {
    plot::DrawTable(picture, args.out);
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
  std::cerr << "plot: wrote " << args.out << " (" << picture.balls.size() << " balls, "
            << picture.events.size() << " events)";
  if (picture.robot_cue) std::cerr << "; " << plot::CueLabel(*picture.robot_cue);
  std::cerr << "\n";
}

}  // namespace

void AddPlotCommand(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw a scene simulated to rest, or a plan, as a PNG or SVG picture of the table: every "
      "ball's path, the events marked, the launch and spin shown, and the robot's cue: its outline, "
      "where it comes nearest what it clears, its elevation");
  cmd->add_option("--scene", args->scene, "A scene file (as simulate --scene reads); its cue on ball 0 is drawn");
  cmd->add_option("--plan", args->plan,
                  "A plan: the JSON of `billiard plan --json`, or of `plan-pot --json` with the --scene it was "
                  "planned on (its stroke strikes ball 0)");
  cmd->add_option("--robot", args->robot,
                  "The robot whose cue is drawn: gantry | player | FILE | none (a plain stick); default "
                  "the plan's, else gantry");
  cmd->add_option("--out", args->out, "The picture: FILE.png or FILE.svg")->required();
  cmd->add_option("--sample-dt", args->sample_dt, "Time between the paths' points [s]")
      ->capture_default_str();
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
