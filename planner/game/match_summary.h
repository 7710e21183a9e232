// A match's figures summed rack by rack, and written as `billiard match --json` prints them; a rack
// shot by shot as `billiard match --shots` logs it.
//
// A rack's part of the figures (RackFigures: who won it, whether its breaker ran it out, each
// player's tally of its shots) depends on the match's seed and the rack's index alone (match.h:
// rack r is seeded SampleSeed(seed, r) and broken by player r % 2). So racks played apart, on
// other processes or machines (tools/python/billiard_dask.py, racks as tasks on a Dask cluster),
// add up with AddRack to the figures of one process playing them in order, as PlayMatch does
// with the same AddRack: one summing code for both.
//
// Each player is listed by rules::MatchPlayerJson (sim/rules/match_standing.h: the win rate with
// its Wilson (1927) interval), as the loop's match lists them, with what only a simulated match
// knows beside: the safeties that worked, the fouls by reason, and the decision times' median and
// 95th percentile by nearest rank (Quantile), each player's and everyone's.
//
// Module: billiard::game.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "planner/game/match.h"

namespace billiard::game {

// One rack's part of a match's figures.
struct RackFigures {
  int winner = -1;  // -1: undecided
  bool break_and_run = false;
  std::array<PlayerTally, 2> players;  // each player's tally of the rack's shots (names unused)
};

// Adds `rack` to `match`'s figures: the players' tallies summed (decision times appended in
// order, fouls by reason merged), the winner's rack and break-and-run, or one more undecided.
// The tallies' names and match->racks are left as they are.
void AddRack(const RackFigures& rack, MatchRecord* match);

// What the summary's header says of the match besides its figures.
struct MatchLabels {
  std::string game;   // "nine-ball" or "eight-ball"
  std::string noise;  // the execution noise's name or file
  std::uint64_t seed = 1;
};

// {"game", "racks", "seed", "noise", "undecided", "players": [{"name", "racks_won", "win_rate",
// "interval95", "break_and_runs", "pots", "attempts", "safeties", "safeties_that_worked",
// "fouls", "foul_reasons", "decision_us": {"median", "p95"}}, ...], "decision_us"}. The racks
// are those the figures hold: the racks won by either player and the undecided ones.
nlohmann::json MatchJson(const MatchRecord& match, const MatchLabels& labels);

// A count of `trials` with its rate and Wilson 95 % interval: {"count", "of", "rate",
// "interval95": [lo, hi]} (rate 0 of no trials).
nlohmann::json RateJson(int count, int trials);

// One rack shot by shot, as `billiard match --shots` logs it a line a rack: {"rack", "breaker",
// "winner" (null when undecided), "reason", "break_and_run", "shots": [game_json.h's ShotJson,
// each with its "player"]}.
nlohmann::json RackJson(const RackResult& rack);

}  // namespace billiard::game
