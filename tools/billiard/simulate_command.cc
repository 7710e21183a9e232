#include "tools/billiard/simulate_command.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "bench/timing.h"
#include "sim/model_choice/model_choice.h"
#include "sim/params/parameter_sets.h"
#include "sim/physics/cue_strike.h"
#include "sim/physics/parameters.h"
#include "sim/physics/simulator.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/scene_commands.h"

namespace billiard::cli {

namespace {

struct SimulateArgs {
  std::string state;
  std::string cue;  // speed,heading,tip_side,tip_height,elevation: a stroke instead of a launch
  std::string at = "0,0";  // where --cue strikes the ball (one ball)
  std::optional<double> t_end;
  std::string scene;
  std::string cushion_model = "mathavan-2010";
  std::string model;  // "": approx for one ball, auto for a scene
  std::string integrator = "rodas4";
  double accuracy = 0.0;  // --model auto only
  std::string params = params::kDefaultParameterSet;
  double tol = physics::SimulationOptions{}.tolerance;
  double quadrature_tol = physics::SimulationOptions{}.quadrature_tolerance;
  std::string trajectory_path;
  double sample_dt = 1e-3;
  std::string scene_out;  // --scene only
  bool no_rest_switch = false;
  std::optional<double> until_speed;
  bool json = false;
};

std::optional<physics::CueStroke> CueOption(const std::string& text) {
  if (text.empty()) return std::nullopt;
  const auto n = ParseNumberList(text, 5, "--cue speed,heading,tip_side,tip_height,elevation");
  return physics::CueStroke{n[0], n[1], n[2], n[3], n[4]};
}

void Run(const SimulateArgs& args, bool at_given) {
  const std::optional<physics::CueStroke> cue = CueOption(args.cue);
  if (!args.scene.empty()) {
    if (!args.state.empty() || at_given) {
      throw UsageError("--scene takes its balls from the file, not --state or --at");
    }
    SimulateScene({args.scene, cue, args.t_end, args.model.empty() ? "auto" : args.model,
                   args.accuracy, args.cushion_model, args.trajectory_path, args.sample_dt,
                   args.scene_out, args.json});
    return;
  }
  if (!args.scene_out.empty()) throw UsageError("--scene-out goes with --scene");
  if (args.state.empty() == !cue) {
    throw UsageError("give one of --state and --cue (one ball), or --scene (a table)");
  }
  if (at_given && !cue) throw UsageError("--at goes with --cue");
  if (!args.t_end) throw UsageError("one ball needs --t-end");
  const double t_end = *args.t_end;
  RequireFinite(t_end, "--t-end");
  if (t_end < 0.0) throw UsageError("--t-end must be >= 0");
  if (!(args.tol > 0.0) || !std::isfinite(args.tol)) throw UsageError("--tol must be positive");
  if (!(args.sample_dt > 0.0) || !std::isfinite(args.sample_dt)) {
    throw UsageError("--sample-dt must be a positive number of seconds");
  }
  const std::string model_name = args.model.empty() ? "approx" : args.model;
  const bool automatic = model_name == "auto";
  const auto model = physics::ParseModel(model_name);
  if (!model && !automatic) {
    throw UsageError("--model: unknown model '" + model_name +
                     "' (approx, integral, closed-form, auto)");
  }
  if (automatic != (args.accuracy != 0.0)) {
    throw UsageError("--model auto and --accuracy METRES go together");
  }
  if (automatic && !(std::isfinite(args.accuracy) && args.accuracy > 0.0)) {
    throw UsageError("--accuracy must be a positive number of metres");
  }
  const auto integrator = physics::ParseIntegrator(args.integrator);
  if (!integrator)
    throw UsageError("--integrator: unknown integrator '" + args.integrator + "' (rodas4, dopri5)");
  const physics::ModelParameters params = LoadParametersOption(args.params);

  physics::BallState initial;
  if (cue) {
    const auto at = ParseNumberList(args.at, 2, "--at X,Y");
    try {
      initial = physics::StrikeBall(*cue, Eigen::Vector2d(at[0], at[1]), params);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--cue: ") + e.what());
    }
  } else {
    const auto numbers = ParseNumberList(args.state, 7, "--state X,Y,vx,vy,wx,wy,wz");
    initial = Eigen::Map<const physics::BallState>(numbers.data());
  }
  physics::SimulationOptions options;
  std::optional<model_choice::ModelChoice> choice;
  if (automatic) {
    choice = model_choice::ChooseModel(initial, params, args.accuracy);
    options = choice->options;
    if (!choice->accuracy_met) {
      std::cerr << "billiard: no measured method reaches " << args.accuracy << " m on "
                << choice->kind << " scenes; using the most accurate (p95 error "
                << choice->expected_error_m << " m)\n";
    }
  } else {
    options.model = *model;
    options.integrator = *integrator;
    options.tolerance = args.tol;
    options.quadrature_tolerance = args.quadrature_tol;
  }
  options.rest_switch = !args.no_rest_switch;
  if (args.until_speed && !(*args.until_speed >= 0.0 && std::isfinite(*args.until_speed))) {
    throw UsageError("--until-speed must be a finite number >= 0");
  }
  // Either to t_end, or to the arrival at a speed with t_end as the limit; timed warm, as a
  // library caller sees it and as `billiard bench` times it (bench/timing.h).
  physics::SimulationResult result;
  double t = t_end;
  std::optional<bool> arrived;
  const double wall_us = bench::MedianWallUs([&] {
    if (args.until_speed) {
      physics::Arrival a =
          physics::SimulateArrival(params, initial, *args.until_speed, t_end, options);
      result.final_state = a.state;
      result.stats = a.stats;
      result.trajectory = std::move(a.trajectory);
      t = a.time;
      arrived = a.reached;
    } else {
      result = physics::Simulate(params, initial, t_end, options);
    }
  });

  if (!args.trajectory_path.empty()) {
    WriteTrajectoryCsv(args.trajectory_path, t, args.sample_dt, 1,
                       [&](double time, int) { return result.trajectory->At(time); });
  }

  const physics::BallState& s = result.final_state;
  if (args.json) {
    nlohmann::json j;
    j["model"] = physics::ModelName(options.model);
    if (options.model != physics::Model::kClosedForm)
      j["integrator"] = physics::IntegratorName(options.integrator);
    if (choice) {
      j["auto"] = {{"accuracy_m", args.accuracy},
                   {"scene_kind", choice->kind},
                   {"expected_error_m", choice->expected_error_m},
                   {"expected_us", choice->expected_us},
                   {"accuracy_met", choice->accuracy_met}};
    }
    DescribeParameters(params, &j);
    if (cue) j["launch"] = std::vector<double>(initial.data(), initial.data() + 7);
    j["t"] = t;
    if (arrived) j["arrived"] = *arrived;
    j["state"] = std::vector<double>(s.data(), s.data() + 7);
    j["steps"] = result.stats.steps;
    j["rejected_steps"] = result.stats.rejected_steps;
    j["rhs_evals"] = result.stats.rhs_evals;
    j["jacobian_evals"] = result.stats.jacobian_evals;
    j["wall_us"] = wall_us;
    j["tol"] = options.tolerance;
    if (result.rest_time >= 0.0) j["rest_time"] = result.rest_time;
    if (result.quadrature) {
      j["quadrature"] = {{"angular_nodes", result.quadrature->order.angular},
                         {"radial_nodes", result.quadrature->order.radial},
                         {"error_estimate", result.quadrature->error_estimate}};
    }
    std::cout << j.dump() << std::endl;
  } else {
    std::cerr << physics::ModelName(options.model) << " model, "
              << params::ParameterSetLabel(params) << " parameters, t = " << t << " s"
              << (arrived && !*arrived ? " (still faster than --until-speed)" : "")
              << "\n  X, Y   = " << s[physics::kX] << ", " << s[physics::kY]
              << " m\n  vx, vy = " << s[physics::kVx] << ", " << s[physics::kVy]
              << " m/s\n  w      = " << s[physics::kWx] << ", " << s[physics::kWy] << ", "
              << s[physics::kWz] << " rad/s\n  " << result.stats.steps << " steps, "
              << result.stats.rhs_evals << " rhs evaluations, " << wall_us << " us\n";
  }
}

}  // namespace

void AddSimulateCommand(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate", "Simulate one ball from an initial state, or every ball of a table scene");
  cmd->add_option("--state", args->state,
                  "Initial state X,Y,vx,vy,wx,wy,wz [m, m/s, rad/s] (write --state=-1,... "
                  "when it starts with a minus sign)");
  cmd->add_option("--cue", args->cue,
                  "A cue stroke instead of a launch: speed [m/s], heading [rad from +x], "
                  "tip_side [m, right english > 0], tip_height [m, follow > 0, draw < 0], "
                  "elevation [rad below horizontal], through the cue strike model with squirt; "
                  "with --scene it strikes the cue ball (id 0), which must be at rest");
  cmd->add_option("--at", args->at, "--cue, one ball: where the ball is struck X,Y [m]")
      ->capture_default_str();
  cmd->add_option("--scene", args->scene,
                  "A table scene (JSON: table, params, balls; `billiard rack` writes one): every "
                  "ball, event by event");
  cmd->add_option("--t-end", args->t_end,
                  "End time [s] (with --until-speed: the longest; a scene without it runs until "
                  "every ball rests or is pocketed)");
  cmd->add_option("--cushion-model", args->cushion_model,
                  "--scene: mathavan-2010 (default) | han-2005")
      ->capture_default_str();
  cmd->add_option("--until-speed", args->until_speed,
                  "Stop where the speed first falls to this [m/s] (0: where the ball comes to "
                  "rest); the JSON's t is that time and \"arrived\" says whether it came");
  cmd->add_option("--model", args->model,
                  "approx (default for --state) | integral | closed-form | auto (the cheapest "
                  "that meets --accuracy; the default for --scene)");
  cmd->add_option("--accuracy", args->accuracy,
                  "--model auto: endpoint error allowed [m], per the measured tables "
                  "(docs/benchmarks)");
  cmd->add_option("--integrator", args->integrator,
                  "5-DOF models: rodas4 (stiff, default) | dopri5 (explicit baseline)")
      ->capture_default_str();
  cmd->add_option("--params", args->params,
                  "paper | pool | path to a JSON parameter file (not with --scene: the scene names its set)")
      ->capture_default_str();
  cmd->add_option("--tol", args->tol, "Integrator local error target [m]")->capture_default_str();
  cmd->add_option("--quadrature-tol", args->quadrature_tol,
                  "Integral model: quadrature error target")
      ->capture_default_str();
  cmd->add_option("--trajectory", args->trajectory_path, "Write the sampled trajectory as CSV");
  cmd->add_option("--scene-out", args->scene_out,
                  "--scene: write the table at the end as a scene (the balls left on it, for "
                  "plan-pot, choose-shot, plot and simulate --scene)");
  cmd->add_option("--sample-dt", args->sample_dt, "Trajectory sampling interval [s]")
      ->capture_default_str();
  cmd->add_flag("--no-rest-switch", args->no_rest_switch,
                "5-DOF models: integrate the regularized equations through the rest phase too");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args, cmd] {
    // The scene names its parameter set (its ball radius placed the balls): one source.
    if (!args->scene.empty() && cmd->count("--params") > 0) {
      throw UsageError("--scene takes its parameter set from the file's \"params\", not --params");
    }
    Run(*args, cmd->count("--at") > 0);
  });
}

}  // namespace billiard::cli
