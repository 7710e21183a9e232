// A match's player over its racks, as every match reports it: `billiard match` and its Dask route
// (planner/game/match_summary.h) and the loop's match through the three nodes
// (sim/table_sim_node/session_summary.h) list their players with this one writer, so that the
// three agree field for field.
//
// The win rate carries the Wilson (1927) score interval at 95 % (sim/batch/wilson.h): a match of
// a few racks is a small binomial sample, where the normal interval would leave [0, 1].
//
// Module: billiard::rules.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace billiard::rules {

// What a match counts of one player over its racks.
struct MatchPlayerCounts {
  int racks_won = 0, break_and_runs = 0, attempts = 0, pots = 0, safeties = 0, fouls = 0;
};

// {"name", "racks_won", "win_rate", "interval95": [lo, hi], "break_and_runs", "pots",
// "attempts", "safeties", "fouls"}, of `racks` racks (a win rate of 0 when none was played).
nlohmann::json MatchPlayerJson(const std::string& name, const MatchPlayerCounts& counts,
                               int racks);

}  // namespace billiard::rules
