#include "tools/billiard/fit_run_out_command.h"

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "planner/game/match_summary.h"
#include "planner/game/run_out_fit.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

struct FitRunOutArgs {
  std::string log;
  int player = 0;
};

// The log's racks counted for args.player; a line that is no rack is a one-line error naming it.
game::RunOutCounts Count(const FitRunOutArgs& args) {
  std::ifstream in(args.log);
  if (!in) throw UsageError("cannot read '" + args.log + "'");
  game::RunOutCounts counts;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    try {
      game::CountRunOut(nlohmann::json::parse(line), args.player, &counts);
    } catch (const nlohmann::json::exception& e) {
      throw UsageError(args.log + ":" + std::to_string(number) + ": not a rack of `billiard match "
                       "--shots` (" + e.what() + ")");
    }
  }
  return counts;
}

// The weighed decisions of one side: how many, their mean estimate, the racks won.
nlohmann::json WeighedJson(const game::RunOutCounts::Weighed& w) {
  return {{"estimated", w.count ? w.estimated / w.count : 0.0},
          {"won", game::RateJson(w.won, w.count)}};
}

void Run(const FitRunOutArgs& args) {
  const game::RunOutCounts c = Count(args);
  const nlohmann::json j = {
      {"player", args.player},
      {"pot_rate", game::RateJson(c.continuing_kept, c.continuing)},
      {"arrival_chance", game::RateJson(c.arriving_kept, c.arriving)},
      {"calibration", {{"safeties", WeighedJson(c.safeties)}, {"attempts", WeighedJson(c.attempts)}}}};
  std::cerr << "player " << args.player << ": kept the table on " << c.continuing_kept << " of "
            << c.continuing << " shots after its own pot, on " << c.arriving_kept << " of "
            << c.arriving << " first shots after the other's miss; safeties weighed and played "
            << c.safeties.count << ", their racks won " << c.safeties.won << ", estimated "
            << c.safeties.estimated << "; attempts weighed and played " << c.attempts.count
            << ", won " << c.attempts.won << ", estimated " << c.attempts.estimated << std::endl;
  std::cout << j.dump() << std::endl;
}

}  // namespace

void AddFitRunOutCommand(CLI::App& app) {
  auto args = std::make_shared<FitRunOutArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit-run-out",
      "The run-out model's rates of one player (the safeties' scale) from `billiard match "
      "--shots LOG`: how often it keeps the table after its own pot and after the other's miss");
  cmd->add_option("log", args->log, "The shot log, a JSON line a rack")->required();
  cmd->add_option("--player", args->player, "The player counted, 0 (A) or 1 (B)")
      ->capture_default_str()->check(CLI::Range(0, 1));
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
