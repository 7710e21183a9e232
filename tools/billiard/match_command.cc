#include "tools/billiard/match_command.h"

#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "planner/game/match.h"
#include "planner/game/match_summary.h"
#include "planner/players/players.h"
#include "sim/batch/thread_pool.h"
#include "sim/params/execution_noise.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "tools/billiard/command_line.h"
#include "tools/billiard/scene_commands.h"

namespace billiard::cli {

namespace {

struct MatchArgs {
  std::string game;
  std::string players;
  int racks = 20;
  std::string noise = params::kDefaultNoise;
  std::uint64_t seed = 1;
  int threads = batch::DefaultThreadCount();
  int shot_limit = 200;
  bool json = false;
  std::string shots;  // the shot log's file; none when empty
};

// "A,B": the two players' names.
std::array<std::string, 2> PlayerNames(const std::string& list) {
  const std::size_t comma = list.find(',');
  if (comma == std::string::npos || list.find(',', comma + 1) != std::string::npos) {
    throw UsageError("--players: give two names, A,B (got '" + list + "')");
  }
  return {list.substr(0, comma), list.substr(comma + 1)};
}

game::MatchOptions OptionsOf(const MatchArgs& args) {
  try {
    return game::OptionsOf({args.game, PlayerNames(args.players), args.noise, args.seed,
                            args.racks, args.shot_limit});
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--") + e.what());  // "--game: ...", as the option is named
  }
}

// One line on stderr as each rack ends: who broke, who won and why, the score so far.
std::string ProgressLine(const game::RackResult& r, const game::MatchRecord& so_far,
                         const std::array<std::string, 2>& names, int racks) {
  std::ostringstream line;
  line << "rack " << r.rack + 1 << "/" << racks << ": " << names[r.breaker] << " broke, "
       << (r.winner < 0 ? std::string("undecided") : names[r.winner] + " won") << " ("
       << r.reason << ", " << r.shots.size() << " shots"
       << (r.break_and_run ? ", break and run" : "") << "); " << names[0] << " "
       << so_far.players[0].racks_won << " - " << so_far.players[1].racks_won << " " << names[1];
  return line.str();
}

void Run(const MatchArgs& args) {
  const game::MatchOptions options = OptionsOf(args);
  const physics::ModelParameters params = LoadParametersOption(params::kDefaultParameterSet);
  const table::TableGeometry table = LoadTableOption(params::kDefaultTable);
  batch::ThreadPool pool(args.threads);
  const std::array<std::string, 2> names = {std::string(options.players[0]->Name()) + " (A)",
                                            std::string(options.players[1]->Name()) + " (B)"};
  std::ofstream log;
  if (!args.shots.empty()) {
    log.open(args.shots);
    if (!log) throw UsageError("--shots: cannot write '" + args.shots + "'");
  }
  game::MatchRecord so_far;
  const game::MatchRecord match =
      game::PlayMatch(table, params, options, pool, [&](const game::RackResult& r) {
        if (r.winner >= 0) ++so_far.players[r.winner].racks_won;
        std::cerr << ProgressLine(r, so_far, names, options.racks) << std::endl;
        if (log.is_open()) log << game::RackJson(r).dump() << std::endl;
      });
  const nlohmann::json j = game::MatchJson(match, {args.game, args.noise, args.seed});
  for (const nlohmann::json& p : j["players"]) {
    std::cerr << p["name"].get<std::string>() << ": " << p["racks_won"] << " racks won of "
              << j["racks"] << std::setprecision(3) << " (95 % "
              << p["interval95"][0].get<double>() << " to " << p["interval95"][1].get<double>()
              << "), " << p["pots"] << " pots of " << p["attempts"] << " attempts, " << p["fouls"]
              << " fouls, " << p["break_and_runs"] << " break-and-runs" << std::endl;
  }
  if (args.json) std::cout << j.dump() << std::endl;
}

}  // namespace

rules::Rules GameOf(const std::string& name) {
  if (name == "nine-ball") return rules::Rules::kNineBall;
  if (name == "eight-ball") return rules::Rules::kEightBall;
  throw UsageError("--game: unknown game '" + name + "' (nine-ball, eight-ball)");
}

void AddMatchCommand(CLI::App& app) {
  auto args = std::make_shared<MatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "match",
      "Two players, racks of nine-ball or eight-ball in simulation with the break alternating, "
      "judged by the rules: racks won (Wilson 95 % interval), pots, fouls, decision times");
  cmd->add_option("--game", args->game, "nine-ball | eight-ball")->required();
  cmd->add_option("--players", args->players,
                  "Two players, A,B (" + players::KnownPlayerList() + "); the first breaks the first rack")
      ->required();
  cmd->add_option("--racks", args->racks, "Racks to play")->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--noise", args->noise,
                  "The execution noise, the table's and the one the players assume: robot | "
                  "computational-pool | a JSON file (sim/params/noise/)")
      ->capture_default_str();
  cmd->add_option("--seed", args->seed, "Seed of the racks, the players' samples and the noise")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  cmd->add_option("--threads", args->threads, "Threads (the results do not depend on them)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_option("--shot-limit", args->shot_limit, "Shots at most in a rack (then undecided)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  cmd->add_flag("--json", args->json, "Print one JSON object on stdout (else on stderr)");
  cmd->add_option("--shots", args->shots,
                  "Log every rack shot by shot to this file, a JSON line a rack as it ends");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
