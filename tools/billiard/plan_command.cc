#include "tools/billiard/plan_command.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "planner/cue_planning.h"
#include "planner/shot_planner.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"
#include "sim/table/scene.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/scene_commands.h"

namespace billiard::cli {

namespace {

struct PlanArgs {
  std::string from, to;
  double final_speed = 0.0;
  std::string spin = "natural";
  double slide = 0.0;  // --slide, when given
  double side_spin = 0.0;
  std::string params = params::kDefaultParameterSet;
  bool no_refine = false;
  std::string robot = params::kDefaultRobot;
  std::string table = params::kDefaultTable;
  bool json = false;
};

// Where the robot's cue is checked: `table_name` (of the parameter set's size), the ball alone
// on it (the point planner knows no other balls).
planner::CueSetting CueSettingOf(const std::string& robot_name, const std::string& table_name,
                                 const physics::ModelParameters& params) {
  const table::TableGeometry table = LoadTableOption(table_name);
  if (std::abs(table.length - params.table.length) > 1e-9 || std::abs(table.width - params.table.width) > 1e-9) {
    throw UsageError("--table " + table_name + " is not the size of the parameter set's table");
  }
  return planner::CueSetting{LoadRobotOption(robot_name), table, {}};
}

nlohmann::json PlanJson(const planner::ShotPlan& plan, const physics::ModelParameters& params) {
  nlohmann::json j;
  j["v0"] = {plan.v0.x(), plan.v0.y()};
  j["w0"] = {plan.w0.x(), plan.w0.y(), plan.w0.z()};
  j["cue"] = CueStrokeJson(plan.stroke);
  j["predicted_final"] = {plan.predicted_final.x(), plan.predicted_final.y()};
  j["closed_form_miss_m"] = plan.closed_form_miss_m;
  j["refined_miss_m"] = plan.refined_miss_m;
  j["solve_us"] = plan.solve_us;
  j["iterations"] = plan.iterations;
  j["arrival_time"] = plan.arrival_time;
  j["slide_length"] = plan.slide_length;
  DescribeParameters(params, &j);
  j["status"] = planner::PlanStatusName(plan.status);
  if (plan.status != planner::PlanStatus::kOk) j["reason"] = plan.reason;
  return j;
}

// The plan as a player reads it: the stroke in degrees, mm and m/s (StrokeInWords), the launch,
// where the ball arrives and by how much it misses, in mm.
void PrintSummary(const planner::ShotPlan& plan, const physics::ModelParameters& params,
                  bool refined) {
  constexpr double kMmPerM = 1000.0;
  std::cerr << "plan, " << params::ParameterSetLabel(params) << " parameters, "
            << (refined ? "refined against the 5-DOF model" : "closed-form inverse alone") << ": "
            << planner::PlanStatusName(plan.status) << "\n  cue     " << StrokeInWords(plan.stroke)
            << "\n  launch  v0 = " << Fixed(plan.v0.x(), 3) << ", " << Fixed(plan.v0.y(), 3)
            << " m/s, w0 = " << Fixed(plan.w0.x(), 2) << ", " << Fixed(plan.w0.y(), 2) << ", "
            << Fixed(plan.w0.z(), 2) << " rad/s, slide " << Fixed(plan.slide_length, 3)
            << " m\n  arrival " << Fixed(plan.predicted_final.x(), 3) << ", "
            << Fixed(plan.predicted_final.y(), 3) << " m at " << Fixed(plan.arrival_time, 3)
            << " s, miss " << Fixed(plan.refined_miss_m * kMmPerM, 2) << " mm (closed form "
            << Fixed(plan.closed_form_miss_m * kMmPerM, 2) << " mm), " << plan.iterations
            << " iterations, " << Fixed(plan.solve_us, 0) << " us\n";
}

void Run(const PlanArgs& args, bool slide_given) {
  const auto from = ParseNumberList(args.from, 2, "--from X,Y");
  const auto to = ParseNumberList(args.to, 2, "--to X,Y");
  RequireFinite(args.final_speed, "--final-speed");
  // Bad input (exit 2), not a plan refused: a ball cannot arrive at a negative speed.
  if (args.final_speed < 0) throw UsageError("--final-speed: must be 0 or more (0: stop at the target)");
  RequireFinite(args.side_spin, "--side-spin");
  planner::ShotRequest request;
  request.from = {from[0], from[1]};
  request.to = {to[0], to[1]};
  request.final_speed = args.final_speed;
  request.side_spin = args.side_spin;
  if (slide_given) {
    RequireFinite(args.slide, "--slide");
    request.slide_length = args.slide;
  } else {
    const auto style = planner::ParseSpinStyle(args.spin);
    if (!style) {
      throw UsageError("--spin: unknown spin '" + args.spin + "' (stun, natural, follow, draw)");
    }
    request.style = *style;
  }
  const physics::ModelParameters params = LoadParametersOption(args.params);
  planner::PlannerOptions options;
  options.refine = !args.no_refine;

  const planner::CueSetting setting = CueSettingOf(args.robot, args.table, params);
  const planner::ShotPlan plan = planner::PlanShotForRobot(request, params, options, setting);
  if (args.json) {
    // The request's ends too, so that the plan alone can be drawn (`billiard plot --plan`).
    nlohmann::json j = PlanJson(plan, params);
    j["from"] = from;
    j["to"] = to;
    j["robot"] = setting.robot.name;
    if (plan.clearance) j["cue"]["clearance"] = ClearanceJson(*plan.clearance);
    std::cout << j.dump() << std::endl;
  }
  if (plan.status != planner::PlanStatus::kOk) {
    throw Refused(planner::PlanStatusName(plan.status) + ": " + plan.reason);
  }
  if (!args.json) PrintSummary(plan, params, options.refine);
}

}  // namespace

void AddPlanCommand(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan", "Plan the cue stroke that sends a ball to a target (exit 3 if the plan is refused)");
  cmd->add_option("--from", args->from,
                  "Ball position X,Y [m] (write --from=-1,0 when it starts with a minus sign)")
      ->required();
  cmd->add_option("--to", args->to, "Target X,Y [m]")->required();
  cmd->add_option("--final-speed", args->final_speed, "Speed at the target [m/s]; 0: stop there")
      ->capture_default_str();
  CLI::Option* spin = cmd->add_option("--spin", args->spin, "stun | natural | follow | draw")
                          ->capture_default_str();
  CLI::Option* slide = cmd->add_option(
      "--slide", args->slide, "Slide length x1 [m] instead of a spin style (excludes --spin)");
  slide->excludes(spin);
  cmd->add_option("--side-spin", args->side_spin, "Side spin wz [rad/s]")->capture_default_str();
  cmd->add_option("--params", args->params, "paper | pool | path to a JSON parameter file")
      ->capture_default_str();
  cmd->add_flag("--no-refine", args->no_refine,
                "The closed-form inverse alone (its miss is still measured with the 5-DOF model)");
  cmd->add_option("--robot", args->robot,
                  "The robot whose cue plays the stroke: gantry | player | FILE (sim/params/robots/); the "
                  "stroke is played at the elevation its cue needs, refused cue_blocked where none clears")
      ->capture_default_str();
  cmd->add_option("--table", args->table, "The table the cue is checked on (the parameter set's size)")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args, slide] { Run(*args, slide->count() > 0); });
}

}  // namespace billiard::cli
