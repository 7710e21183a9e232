// `billiard match`: two players, racks of nine-ball or eight-ball in simulation, the break
// alternating, judged by the rules (planner/game/match.h); each player's racks won with the
// Wilson interval, pots, attempts, fouls and break-and-runs, and the decision times.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner/game/match.h"
#include "sim/rules/rules.h"

namespace billiard::cli {

// A --game option's game: "nine-ball" or "eight-ball"; UsageError otherwise.
rules::Rules GameOf(const std::string& name);

void AddMatchCommand(CLI::App& app);

}  // namespace billiard::cli
