#include "tools/billiard/fit_shots_command.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "lcmtypes/billiard/cue_command_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/shot_fit.h"
#include "sim/shot_fit/shot_recorder.h"
#include "sim/shot_fit/uncertainty.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/logged_shots.h"
#include "plot/table_picture.h"

namespace billiard::cli {

namespace {

// The parameter set fit-shots uses on a table unless --params says otherwise: the constants
// identified from the dev shots for the carom table (sim/params/carom-fitted.json).
std::string DefaultParameters(const std::string& table) {
  return table == "carom-10ft" ? "carom-fitted" : params::kDefaultParameterSet;
}

struct FitShotsArgs {
  std::string shots, table = "carom-10ft", params, fit_physics, out_params, plot_dir;
  int plot_worst = 3, hold_out_every = 0, threads = batch::DefaultThreadCount(), rounds = 1;
  bool fit_elevation = false, json = false;
};

// The table of a --table option; UsageError if it does not load.
table::TableGeometry TableOption(const std::string& name_or_path) {
  try {
    return table::BuildTable(params::LoadTableSpec(name_or_path));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--table: ") + e.what());
  }
}

nlohmann::json StrikeJson(const shot_fit::Strike& s) {
  nlohmann::json offsets = nlohmann::json::array();
  for (const Eigen::Vector2d& d : s.start_offsets) offsets.push_back({d.x(), d.y()});
  return {{"speed_m_s", s.stroke.speed},         {"heading_rad", s.stroke.heading},
          {"tip_side_m", s.stroke.tip_side},     {"tip_height_m", s.stroke.tip_height},
          {"elevation_rad", s.stroke.elevation}, {"time_s", s.time},
          {"start_offsets_m", offsets}};
}

nlohmann::json ConstantsJson(const shot_fit::ShotsFit& fit) {
  nlohmann::json out = nlohmann::json::object();
  for (const shot_fit::ConstantFit& c : fit.constants) {
    out[shot_fit::ConstantName(c.constant)] = {
        {"value", c.value},
        {"prior", c.prior},
        {"sd", std::isfinite(c.sd) ? nlohmann::json(c.sd) : nlohmann::json(nullptr)},
        {"at_bound", c.at_bound},
        {"identifiable", c.identifiable}};
  }
  return out;
}

// The fit's options of --fit-physics and --rounds; UsageError on an unknown constant.
shot_fit::FitOptions JointFitOptions(const std::string& fit_physics, int rounds) {
  shot_fit::FitOptions options;
  options.rounds = rounds;
  try {
    options.constants = shot_fit::ParseConstants(fit_physics);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--fit-physics: ") + e.what());
  }
  return options;
}

// Shots the fit could not follow.
int FailedShots(const shot_fit::ShotsFit& fit) {
  return static_cast<int>(std::count_if(fit.shots.begin(), fit.shots.end(),
                                        [](const shot_fit::ShotFit& s) { return !s.ok(); }));
}

// What fit-shots and identify print: each shot's RMSE and strike (or why it has none), the
// median, the constants, "params": the set the strikes were fitted with (the prior with the
// fitted constants), and "prior": the given set's name and file.
nlohmann::json FitJson(const shot_fit::ShotsFit& fit, const physics::ModelParameters& prior) {
  nlohmann::json shots = nlohmann::json::array();
  for (const shot_fit::ShotFit& s : fit.shots) {
    nlohmann::json j = {{"id", s.id}, {"held_out", s.held_out}};
    if (!s.ok()) {
      j["error"] = s.error;
    } else {
      j["rmse_m"] = {{"cue", s.rmse_cue}, {"all", s.errors.rmse_all}};
      j["strike"] = StrikeJson(s.strike);
    }
    shots.push_back(j);
  }
  return {{"shots", shots},
          {"median_cue_rmse_m", fit.median_cue_rmse},
          {"constants", ConstantsJson(fit)},
          {"constant_shots", fit.constant_shots},
          {"residual_correlation_samples", fit.correlation_time},
          {"params", nlohmann::json::parse(params::ParametersJson(fit.params))},
          {"prior", params::ParameterSetLabel(prior)}};
}

// The prior with the fitted constants, named "<prior>-fitted", into `path` with the fit's
// report (`report`, the command and the constants) as its "fit".
void WriteFittedSet(const std::string& path, const std::string& option,
                    const shot_fit::ShotsFit& fit, const physics::ModelParameters& prior,
                    const std::string& command, nlohmann::json report,
                    const std::string& fitted_to) {
  report["command"] = "billiard " + command;
  report["prior"] = params::ParameterSetLabel(prior);
  report["constants"] = ConstantsJson(fit);
  report["constant_shots"] = fit.constant_shots;
  report["residual_correlation_samples"] = fit.correlation_time;
  report["median_cue_rmse_m"] = fit.median_cue_rmse;
  physics::ModelParameters out_set = fit.params;
  out_set.name = prior.name + "-fitted";
  out_set.uncertainty.sd = shot_fit::SetUncertainty(fit.constants, fit.params);
  out_set.uncertainty.source = "The fitted constants' standard uncertainties (\"fit\": constants)";
  out_set.source = "The constants of \"fit\" fitted by billiard " + command + " to " +
                   std::to_string(fit.constant_shots) + " " + fitted_to +
                   "; the other numbers those of " + params::ParameterSetLabel(prior) + ": " +
                   prior.source;
  std::ofstream file(path);
  if (!file) throw UsageError(option + ": cannot write " + path);
  file << params::ParametersJson(out_set, report.dump());
}

// The constants on stderr, each fitted with its uncertainty or kept at the prior.
void PrintConstants(const shot_fit::ShotsFit& fit) {
  for (const shot_fit::ConstantFit& c : fit.constants) {
    std::cerr << "  " << shot_fit::ConstantName(c.constant) << " = " << c.value;
    if (c.identifiable) {
      std::cerr << " +- " << c.sd << " (prior " << c.prior << ")\n";
    } else if (c.at_bound) {
      std::cerr << ": its fit ran to the edge of its range, kept at the prior\n";
    } else {
      std::cerr << ": not identifiable from these shots, kept at the prior\n";
    }
  }
  if (!fit.constants.empty()) {
    std::cerr << "  (uncertainties with the residuals' correlation over "
              << fit.correlation_time << " samples)\n";
  }
}

// A progress line on stderr, rewritten in place, when stderr is a terminal.
shot_fit::FitProgress TerminalProgress(const std::string& command = "fit-shots") {
  if (!isatty(STDERR_FILENO)) return nullptr;
  return [command](const std::string& stage, std::size_t done, std::size_t total) {
    std::cerr << "\r" << command << ": " << stage << " " << done << "/" << total << "   " << std::flush;
    if (done == total) std::cerr << "\n";
  };
}

// Carom's colours from pool's numbers: the cue ball white (0), the others yellow (1) and red (3).
int PictureId(std::size_t ball, std::size_t cue) {
  if (ball == cue) return 0;
  return (ball < cue ? ball : ball - 1) == 0 ? 1 : 3;
}

// The shot tracked (dots) against its fitted strike simulated (lines), into `path`.
void DrawShot(const table::TableGeometry& table, const physics::ModelParameters& p,
              const shot_fit::TrackedShot& shot, const shot_fit::ShotFit& fit,
              const std::string& path) {
  const table::TableSimulation sim = shot_fit::SimulateShot(table, p, shot, fit.strike);
  plot::TablePicture picture;
  picture.table = table;
  picture.ball_radius = p.ball.radius;
  plot::AddSimulation(sim, plot::kPathSampleDt, &picture);
  for (std::size_t i = 0; i < shot.balls.size(); ++i) {
    picture.balls[i].id = PictureId(i, shot.cue);
    picture.tracked.push_back({PictureId(i, shot.cue), shot.balls[i].position});
  }
  // The cue is drawn at the first ball.
  std::rotate(picture.balls.begin(), picture.balls.begin() + shot.cue,
              picture.balls.begin() + shot.cue + 1);
  picture.cue = fit.strike.stroke;
  std::ostringstream title;
  title << "shot " << shot.id << (fit.held_out ? " (held out)" : "") << ": tracked (dots), "
        << p.name << " (lines); RMSE cue " << std::setprecision(3) << 100.0 * fit.rmse_cue
        << " cm, all " << 100.0 * fit.errors.rmse_all << " cm";
  picture.title = title.str();
  plot::DrawTable(picture, path);
}

// The `count` shots of largest cue-ball RMSE, drawn into `dir` as shot_<id>.png.
void DrawWorst(const table::TableGeometry& table, const shot_fit::ShotsFit& fit,
               const std::vector<shot_fit::TrackedShot>& shots, int count, const std::string& dir) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < fit.shots.size(); ++i)
    if (fit.shots[i].ok()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return fit.shots[a].rmse_cue > fit.shots[b].rmse_cue;
  });
  order.resize(std::min<std::size_t>(order.size(), static_cast<std::size_t>(count)));
  for (std::size_t i : order) {
    const std::string path = dir + "/shot_" + shots[i].id + ".png";
    DrawShot(table, fit.params, shots[i], fit.shots[i], path);
    std::cerr << "fit-shots: drew " << path << "\n";
  }
}

void Run(const FitShotsArgs& args) {
  if (args.hold_out_every < 0 || args.hold_out_every == 1)
    throw UsageError("--hold-out-every must be 0 (none) or >= 2");
  if (args.threads < 1) throw UsageError("--threads must be >= 1");
  if (args.rounds < 1) throw UsageError("--rounds must be >= 1");
  if (args.plot_worst < 0) throw UsageError("--plot-worst must be >= 0");
  if (!args.plot_dir.empty()) RequireWritableDirectory(args.plot_dir, "--plot-dir");
  shot_fit::FitOptions options = JointFitOptions(args.fit_physics, args.rounds);
  options.fit_elevation = args.fit_elevation;
  const table::TableGeometry table = TableOption(args.table);
  const physics::ModelParameters p =
      LoadParametersOption(args.params.empty() ? DefaultParameters(args.table) : args.params);
  shot_fit::TrackedShots tracked;
  try {
    tracked = shot_fit::ReadTrackedShots(args.shots);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (tracked.shots.empty()) throw UsageError(args.shots + ": holds no shots");
  std::vector<bool> held_out(tracked.shots.size(), false);
  if (args.hold_out_every > 0) {
    for (std::size_t i = 0; i < held_out.size(); ++i)
      held_out[i] = (i + 1) % static_cast<std::size_t>(args.hold_out_every) == 0;
  }

  const auto started = std::chrono::steady_clock::now();
  batch::ThreadPool pool(args.threads);
  const shot_fit::ShotsFit fit =
      shot_fit::FitShots(table, p, tracked.shots, options, pool, held_out, TerminalProgress());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  nlohmann::json out = FitJson(fit, p);
  out["table"] = args.table;
  out["seconds"] = seconds;
  out["threads"] = args.threads;
  if (args.hold_out_every > 0) out["held_out_median_cue_rmse_m"] = fit.held_out_median_cue_rmse;
  if (!args.out_params.empty()) {
    nlohmann::json report = {{"shots_file", args.shots},
                             {"shots_source", tracked.source},
                             {"table", args.table}};
    if (args.hold_out_every > 0) {
      report["hold_out_every"] = args.hold_out_every;
      report["held_out_median_cue_rmse_m"] = fit.held_out_median_cue_rmse;
    }
    std::vector<double> held_out_rmse;
    for (const shot_fit::ShotFit& s : fit.shots)
      if (s.ok() && s.held_out) held_out_rmse.push_back(s.rmse_cue);
    std::sort(held_out_rmse.begin(), held_out_rmse.end());
    if (!held_out_rmse.empty()) report["held_out_sorted_cue_rmse_m"] = held_out_rmse;
    WriteFittedSet(args.out_params, "--out-params", fit, p, "fit-shots", report,
                   "tracked shots of " + args.shots);
  }
  if (!args.plot_dir.empty()) DrawWorst(table, fit, tracked.shots, args.plot_worst, args.plot_dir);
  if (args.json) std::cout << out.dump() << std::endl;
  std::cerr << "fit-shots: " << fit.shots.size() << " shots (" << FailedShots(fit)
            << " failed) in " << seconds << " s; median cue-ball RMSE " << fit.median_cue_rmse
            << " m";
  if (args.hold_out_every > 0)
    std::cerr << ", held out " << fit.held_out_median_cue_rmse << " m";
  std::cerr << "\n";
  PrintConstants(fit);
}

struct BenchShotFitArgs {
  int shots = 60, threads = batch::DefaultThreadCount();
  std::uint64_t seed = 28;
  double spread = 0.2;
  std::string fit_physics = "mu,rolling,cushion", params = "carom", table = "carom-10ft";
  bool json = false;
};

// Synthetic truth: the constants hidden within +-spread of the set's, shots simulated and
// tracked with them (shot_fit::SyntheticShots), fitted from the set's values.
void RunBench(const BenchShotFitArgs& args) {
  if (args.shots < 1) throw UsageError("--shots must be >= 1");
  if (!(args.spread >= 0.0 && args.spread < 1.0)) throw UsageError("--spread must lie in [0, 1)");
  if (args.threads < 1) throw UsageError("--threads must be >= 1");
  shot_fit::FitOptions options;
  try {
    options.constants = shot_fit::ParseConstants(args.fit_physics);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--fit-physics: ") + e.what());
  }
  const table::TableGeometry table = TableOption(args.table);
  const physics::ModelParameters prior = LoadParametersOption(args.params);
  std::mt19937_64 random(args.seed);
  std::uniform_real_distribution<double> factor(1.0 - args.spread, 1.0 + args.spread);
  std::vector<double> hidden;
  for (shot_fit::Constant c : options.constants)
    hidden.push_back(shot_fit::ConstantValue(prior, c) * factor(random));
  const physics::ModelParameters truth = shot_fit::WithConstants(prior, options.constants, hidden);
  const std::vector<shot_fit::TrackedShot> shots =
      shot_fit::SyntheticShots(table, truth, args.shots, args.seed);
  const auto started = std::chrono::steady_clock::now();
  batch::ThreadPool pool(args.threads);
  const shot_fit::ShotsFit fit =
      shot_fit::FitShots(table, prior, shots, options, pool, {}, TerminalProgress());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  nlohmann::json constants = nlohmann::json::object();
  for (std::size_t c = 0; c < fit.constants.size(); ++c) {
    const shot_fit::ConstantFit& f = fit.constants[c];
    const double error = f.value / hidden[c] - 1.0;
    constants[shot_fit::ConstantName(f.constant)] = {
        {"hidden", hidden[c]}, {"prior", f.prior},  {"fitted", f.value},
        {"sd", f.sd},          {"relative_error", error}, {"identifiable", f.identifiable}};
    std::cerr << "bench-shot-fit: " << shot_fit::ConstantName(f.constant) << " hidden "
              << hidden[c] << ", fitted " << f.value << " +- " << f.sd << " ("
              << 100.0 * error << " %)\n";
  }
  std::cerr << "bench-shot-fit: " << args.shots << " shots in " << seconds
            << " s; median cue-ball RMSE " << fit.median_cue_rmse << " m\n";
  if (args.json) {
    std::cout << nlohmann::json{{"shots", args.shots},     {"seed", args.seed},
                                {"spread", args.spread},   {"constants", constants},
                                {"median_cue_rmse_m", fit.median_cue_rmse},
                                {"seconds", seconds},      {"threads", args.threads}}
                     .dump()
              << std::endl;
  }
}


struct IdentifyArgs {
  std::string log, out, shots_out, params = params::kDefaultParameterSet,
                                   table = params::kDefaultTable,
                                   fit_physics = "mu,rolling,cushion", tracks = "estimator";
  int threads = batch::DefaultThreadCount(), rounds = 1;
  bool json = false;
};

void RunIdentify(const IdentifyArgs& args) {
  if (args.threads < 1) throw UsageError("--threads must be >= 1");
  if (args.rounds < 1) throw UsageError("--rounds must be >= 1");
  const shot_fit::FitOptions options = JointFitOptions(args.fit_physics, args.rounds);
  const table::TableGeometry table = TableOption(args.table);
  const physics::ModelParameters p = LoadParametersOption(args.params);
  if (std::abs(table.length - p.table.length) > 1e-9 ||
      std::abs(table.width - p.table.width) > 1e-9) {
    throw UsageError("--table " + args.table + " is not the size of the parameter set's table");
  }
  if (args.tracks != "estimator" && args.tracks != "truth")
    throw UsageError("--tracks must be estimator or truth, not '" + args.tracks + "'");
  const LoggedShots logged = ReadLoggedShots(args.log, args.tracks == "truth");
  std::cerr << "identify: " << logged.shots.size() << " shots from " << logged.strikes
            << " commanded strikes and " << logged.states << " table states of " << args.log
            << "\n";
  if (!args.shots_out.empty()) {
    shot_fit::TrackedShots cut;
    cut.source = "shots of the loop recorded in " + args.log + ", the " +
                 (args.tracks == "truth" ? "simulator's truth" : "estimator's tracks");
    cut.shots = logged.shots;
    std::ofstream file(args.shots_out);
    if (!file) throw UsageError("--shots-out: cannot write " + args.shots_out);
    file << shot_fit::TrackedShotsJson(cut);
  }
  const auto started = std::chrono::steady_clock::now();
  batch::ThreadPool pool(args.threads);
  const shot_fit::ShotsFit fit =
      shot_fit::FitShots(table, p, logged.shots, options, pool, {}, TerminalProgress("identify"));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const nlohmann::json log = {{"file", args.log},          {"tracks", args.tracks},
                              {"events", logged.events},
                              {"table_states", logged.states}, {"strikes", logged.strikes},
                              {"refused", logged.refused}, {"undecodable", logged.undecodable},
                              {"skipped", logged.skipped}};
  if (!args.out.empty()) {
    WriteFittedSet(args.out, "--out", fit, p, "identify", {{"log", log}, {"table", args.table}},
                   "shots of the loop recorded in " + args.log);
  }
  nlohmann::json out = FitJson(fit, p);
  out["log"] = log;
  out["table"] = args.table;
  out["seconds"] = seconds;
  out["threads"] = args.threads;
  if (args.json) std::cout << out.dump() << std::endl;
  std::cerr << "identify: " << fit.shots.size() << " shots (" << FailedShots(fit) << " failed) in "
            << seconds << " s; median cue-ball RMSE " << fit.median_cue_rmse << " m\n";
  PrintConstants(fit);
}

}  // namespace

void AddIdentifyCommand(CLI::App& app) {
  auto args = std::make_shared<IdentifyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "identify",
      "Fit the physics constants (and each shot's strike) to a recorded run of the loop: its "
      "commanded strikes and the estimator's tracks (docs/identification.md)");
  cmd->add_option("LOG", args->log, "LCM log (run_loop.sh --log FILE; the frames not needed)")
      ->required();
  cmd->add_option("--out", args->out,
                  "Write the identified parameter set, with the fit's report, to this file");
  cmd->add_option("--params", args->params, "The loop's parameter set, the fit's prior")
      ->capture_default_str();
  cmd->add_option("--table", args->table, "The loop's table: a built-in name or a JSON file")
      ->capture_default_str();
  cmd->add_option("--fit-physics", args->fit_physics,
                  "Constants fitted jointly over the shots: mu,rolling,spin,cushion,"
                  "cushion_friction,ball_ball")
      ->capture_default_str();
  cmd->add_option("--rounds", args->rounds,
                  "Rounds of the joint fit over whole shots after the continuation")
      ->capture_default_str();
  cmd->add_option("--shots-out", args->shots_out,
                  "Write the shots cut from the log, in fit-shots' format, to this file");
  cmd->add_option("--tracks", args->tracks,
                  "The shots' samples: the estimator's TABLE_STATE, or the simulator's "
                  "TABLE_TRUTH (truth: what the fit does without the tracking's errors)")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunIdentify(*args); });
}

void AddBenchShotFitCommand(CLI::App& app) {
  auto args = std::make_shared<BenchShotFitArgs>();
  CLI::App* cmd = app.add_subcommand(
      "bench-shot-fit", "Recover hidden physics constants from simulated, tracked shots");
  cmd->add_option("--shots", args->shots, "Synthetic shots")->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the constants and the shots")
      ->capture_default_str();
  cmd->add_option("--spread", args->spread, "Hidden constants within +- this of the set's")
      ->capture_default_str();
  cmd->add_option("--fit-physics", args->fit_physics, "Constants to recover")
      ->capture_default_str();
  cmd->add_option("--params", args->params, "The set the constants are hidden around")
      ->capture_default_str();
  cmd->add_option("--table", args->table, "Table")->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads")->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunBench(*args); });
}

void AddFitShotsCommand(CLI::App& app) {
  auto args = std::make_shared<FitShotsArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit-shots", "Fit each tracked shot's cue strike (and shared physics constants) through the "
                   "whole-table simulation");
  cmd->add_option("--shots", args->shots, "Tracked shots (JSON, docs/identification.md)")
      ->required();
  cmd->add_option("--table", args->table, "Table: a built-in name or a JSON file")
      ->capture_default_str();
  cmd->add_option("--params", args->params,
                  "Parameter set (default: carom-fitted on carom-10ft, else pool)");
  cmd->add_option("--fit-physics", args->fit_physics,
                  "Constants fitted jointly over the shots: mu,rolling,spin,cushion,"
                  "cushion_friction,ball_ball");
  cmd->add_flag("--fit-elevation", args->fit_elevation, "Fit the cue's elevation too");
  cmd->add_option("--hold-out-every", args->hold_out_every,
                  "Hold every K-th shot out of the constants' fit and report it apart")
      ->capture_default_str();
  cmd->add_option("--rounds", args->rounds, "Rounds of the joint fit over whole shots after the continuation")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads")->capture_default_str();
  cmd->add_option("--out-params", args->out_params,
                  "Write the fitted parameter set, with the fit's report, to this file");
  cmd->add_option("--plot-dir", args->plot_dir,
                  "Draw the worst shots, tracked against simulated, into this directory");
  cmd->add_option("--plot-worst", args->plot_worst, "How many shots --plot-dir draws")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
