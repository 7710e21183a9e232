#include "tools/billiard/identify_noise_command.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "planner/node/noise_learning.h"
#include "sim/params/execution_noise.h"
#include "sim/params/noise_file.h"
#include "sim/params/parameter_sets.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/logged_shots.h"
#include "tools/billiard/noise_option.h"

namespace billiard::cli {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

struct IdentifyNoiseArgs {
  std::string log, params = params::kDefaultParameterSet, prior = params::kDefaultNoise,
                   tracks = "estimator", noise_out;
  bool json = false;
};

// A spread in the units of sim/params/noise/'s files.
nlohmann::json SpreadJson(const shot_fit::Spread& s, double unit) {
  return {{"value", s.value / unit}, {"sd", s.sd / unit},          {"lower", s.lower / unit},
          {"upper", s.upper / unit}, {"identified", s.identified}};
}

// The bias of each spin style, in the residual's coordinates.
nlohmann::json BiasJson(const shot_fit::NoiseFit& fit) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [style, b] : fit.bias) {
    out.push_back({{"spin_ratio", style / shot_fit::kStylesPerUnitSpin},
                   {"log_speed", b[0]},
                   {"direction_deg", b[1] / kDegree},
                   {"log_rolling_speed", b[2]},
                   {"rolling_direction_deg", b[3] / kDegree}});
  }
  return out;
}

void RunIdentifyNoise(const IdentifyNoiseArgs& args) {
  if (args.tracks != "estimator" && args.tracks != "truth")
    throw UsageError("--tracks must be estimator or truth, not '" + args.tracks + "'");
  const physics::ModelParameters p = LoadParametersOption(args.params);
  const params::ExecutionNoise prior = LoadNoiseOption(args.prior, "--prior");
  const LoggedShots logged = ReadLoggedShots(args.log, args.tracks == "truth");
  planner_node::NoiseLearner learner(prior);
  for (const cue_command_t& command : logged.commands) learner.Commanded(command);
  if (!learner.Learn(logged.shots, logged.strike_utimes, p)) {
    throw UsageError("'" + args.log + "': " + std::to_string(learner.launches()) +
                     " launches measured of " + std::to_string(logged.shots.size()) +
                     " shots, " + std::to_string(planner_node::kMinNoiseShots) +
                     " needed: nothing to learn the noise from");
  }
  const shot_fit::NoiseFit& fit = *learner.fit();
  nlohmann::json used = nlohmann::json::array();
  for (std::size_t i : fit.used) used.push_back(logged.shots[learner.launch_shots()[i]].id);
  const nlohmann::json out = {
      {"log", {{"file", args.log}, {"tracks", args.tracks}, {"strikes", logged.strikes},
               {"table_states", logged.states}, {"skipped", logged.skipped}}},
      {"prior", prior.name},
      {"shots", logged.shots.size()},
      {"launches", learner.launches()},
      {"unmeasured", learner.unmeasured()},
      {"rejected", fit.rejected},
      {"shots_used", used},
      {"learned_noise",
       {{"speed_fraction", SpreadJson(fit.speed, 1.0)},
        {"heading_deg", SpreadJson(fit.heading, kDegree)},
        {"tip_mm", SpreadJson(fit.tip, 1e-3)}}},
      {"bias", BiasJson(fit)}};
  if (!args.noise_out.empty()) {
    std::ofstream file(args.noise_out);
    if (!(file << params::FormatNoise(learner.noise()))) {
      throw UsageError("--noise-out: cannot write '" + args.noise_out + "'");
    }
  }
  if (args.json) std::cout << out.dump() << std::endl;
  std::cerr << "identify-noise: " << learner.Describe() << "\n";
}

}  // namespace

void AddIdentifyNoiseCommand(CLI::App& app) {
  auto args = std::make_shared<IdentifyNoiseArgs>();
  CLI::App* cmd = app.add_subcommand(
      "identify-noise",
      "Measure the robot's execution noise from a recorded run of the loop: each commanded "
      "stroke against the launch the estimator tracked (docs/identification.md)");
  cmd->add_option("LOG", args->log, "LCM log (run_loop.sh --log FILE; the frames not needed)")
      ->required();
  cmd->add_option("--params", args->params, "The loop's parameter set (its cue model)")
      ->capture_default_str();
  cmd->add_option("--prior", args->prior,
                  "The noise the planner was told of (a name or a file): the tip's spread is "
                  "held at its value where the launches do not identify it")
      ->capture_default_str();
  cmd->add_option("--tracks", args->tracks,
                  "The launches from the estimator's TABLE_STATE, or the simulator's TABLE_TRUTH")
      ->capture_default_str();
  cmd->add_option("--noise-out", args->noise_out,
                  "Write the learned noise as a noise file (the prior with the learned spreads), "
                  "which --noise of choose-shot, play and bench-game reads");
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout");
  cmd->callback([args] { RunIdentifyNoise(*args); });
}

}  // namespace billiard::cli
