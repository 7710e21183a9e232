// The shot-choice subcommands: `billiard choose-shot` (which pot to play under the robot's
// execution noise), `billiard play` (a rack played shot by shot in simulation) and `billiard
// bench-game` (calibration, baselines and decision time on seeded nine-ball layouts).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "planner/choice/choice_result.h"
#include "planner/game/game.h"

namespace billiard::cli {

// A choice as `choose-shot --json` prints it.
nlohmann::json ChoiceJson(const choice::ChoiceResult& result);

void AddChooseShotCommand(CLI::App& app);
void AddPlayCommand(CLI::App& app);
void AddBenchGameCommand(CLI::App& app);

}  // namespace billiard::cli
