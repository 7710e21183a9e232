#include "tools/billiard/fit_shots_command.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "sim/batch/thread_pool.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/shot_fit/shot_fit.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

// The parameter set fit-shots uses on a table unless --params says otherwise: the constants
// identified from the dev shots for the carom table (sim/params/carom-fitted.json).
std::string DefaultParameters(const std::string& table) {
  return table == "carom-10ft" ? "carom-fitted" : params::kDefaultParameterSet;
}

struct FitShotsArgs {
  std::string shots, table = "carom-10ft", params, fit_physics, out_params;
  int hold_out_every = 0, threads = batch::DefaultThreadCount(), rounds = 3;
  bool fit_elevation = false, json = false;
};

nlohmann::json StrikeJson(const shot_fit::Strike& s) {
  return {{"speed_m_s", s.stroke.speed},     {"heading_rad", s.stroke.heading},
          {"tip_side_m", s.stroke.tip_side}, {"tip_height_m", s.stroke.tip_height},
          {"elevation_rad", s.stroke.elevation}, {"time_s", s.time}};
}

nlohmann::json ConstantsJson(const shot_fit::ShotsFit& fit) {
  nlohmann::json out = nlohmann::json::object();
  for (const shot_fit::ConstantFit& c : fit.constants) {
    out[shot_fit::ConstantName(c.constant)] = {
        {"value", c.value},
        {"prior", c.prior},
        {"sd", std::isfinite(c.sd) ? nlohmann::json(c.sd) : nlohmann::json(nullptr)},
        {"identifiable", c.identifiable}};
  }
  return out;
}

// A progress line on stderr, rewritten in place, when stderr is a terminal.
shot_fit::FitProgress TerminalProgress() {
  if (!isatty(STDERR_FILENO)) return nullptr;
  return [](const std::string& stage, std::size_t done, std::size_t total) {
    std::cerr << "\rfit-shots: " << stage << " " << done << "/" << total << "   " << std::flush;
    if (done == total) std::cerr << "\n";
  };
}

void Run(const FitShotsArgs& args) {
  if (args.hold_out_every < 0 || args.hold_out_every == 1)
    throw UsageError("--hold-out-every must be 0 (none) or >= 2");
  if (args.threads < 1) throw UsageError("--threads must be >= 1");
  if (args.rounds < 1) throw UsageError("--rounds must be >= 1");
  shot_fit::FitOptions options;
  options.fit_elevation = args.fit_elevation;
  options.rounds = args.rounds;
  try {
    options.constants = shot_fit::ParseConstants(args.fit_physics);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--fit-physics: ") + e.what());
  }
  const table::TableGeometry table = table::BuildTable(params::LoadTableSpec(args.table));
  const physics::ModelParameters p =
      LoadParametersOption(args.params.empty() ? DefaultParameters(args.table) : args.params);
  const shot_fit::TrackedShots tracked = shot_fit::ReadTrackedShots(args.shots);
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

  nlohmann::json shots = nlohmann::json::array();
  int failed = 0;
  for (const shot_fit::ShotFit& s : fit.shots) {
    nlohmann::json j = {{"id", s.id}, {"held_out", s.held_out}};
    if (!s.ok()) {
      j["error"] = s.error;
      ++failed;
    } else {
      j["rmse_m"] = {{"cue", s.rmse_cue}, {"all", s.errors.rmse_all}};
      j["strike"] = StrikeJson(s.strike);
    }
    shots.push_back(j);
  }
  nlohmann::json out = {{"shots", shots},
                        {"median_cue_rmse_m", fit.median_cue_rmse},
                        {"table", args.table},
                        {"constants", ConstantsJson(fit)},
                        {"constant_shots", fit.constant_shots},
                        {"seconds", seconds},
                        {"threads", args.threads}};
  if (args.hold_out_every > 0) out["held_out_median_cue_rmse_m"] = fit.held_out_median_cue_rmse;
  out["params"] = nlohmann::json::parse(params::ParametersJson(fit.params));
  DescribeParameters(p, &out);
  if (!args.out_params.empty()) {
    nlohmann::json report = {{"command", "billiard fit-shots"},
                             {"shots_file", args.shots},
                             {"shots_source", tracked.source},
                             {"prior", params::ParameterSetLabel(p)},
                             {"table", args.table},
                             {"constants", ConstantsJson(fit)},
                             {"constant_shots", fit.constant_shots},
                             {"median_cue_rmse_m", fit.median_cue_rmse}};
    if (args.hold_out_every > 0) {
      report["hold_out_every"] = args.hold_out_every;
      report["held_out_median_cue_rmse_m"] = fit.held_out_median_cue_rmse;
    }
    std::ofstream file(args.out_params);
    if (!file) throw UsageError("--out-params: cannot write " + args.out_params);
    file << params::ParametersJson(fit.params, report.dump());
  }
  if (args.json) std::cout << out.dump() << std::endl;
  std::cerr << "fit-shots: " << fit.shots.size() << " shots (" << failed << " failed) in "
            << seconds << " s; median cue-ball RMSE " << fit.median_cue_rmse << " m";
  if (args.hold_out_every > 0)
    std::cerr << ", held out " << fit.held_out_median_cue_rmse << " m";
  std::cerr << "\n";
  for (const shot_fit::ConstantFit& c : fit.constants) {
    std::cerr << "  " << shot_fit::ConstantName(c.constant) << " = " << c.value;
    if (c.identifiable) {
      std::cerr << " +- " << c.sd << " (prior " << c.prior << ")\n";
    } else {
      std::cerr << ": not identifiable from these shots, kept at the prior\n";
    }
  }
}

}  // namespace

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
  cmd->add_option("--rounds", args->rounds, "Rounds of strikes then constants")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads")->capture_default_str();
  cmd->add_option("--out-params", args->out_params,
                  "Write the fitted parameter set, with the fit's report, to this file");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
