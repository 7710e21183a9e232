// The shot choice's benchmark (planner/choice/), on seeded nine-ball layouts
// (choice::SeededNineBallLayout) on the pool-9ft table:
//  - calibration: the finalists of seeded choices (a seeded cue ball, nine-ball rules, the robot's
//    noise), each played `executions` more times with fresh noise on the full model: the
//    measured pot rate against the predicted probability, per decile (a reliability diagram);
//  - games: each layout a drill from ball in hand, one visit (until a shot pots nothing or
//    fouls), under the robot's noise and under the computational-pool noise, played by ours, by
//    ours without the lookahead and by the easiest-looking ghost-ball shot: pots per attempt,
//    run-outs, fouls;
//  - decision time: the choices' wall time (ChooseShot, no ball in hand), and whether one
//    thread and two give the same choice.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner/choice/game.h"

namespace billiard::bench {

struct GameBenchmarkOptions {
  int layouts = 500;              // drills per noise and policy
  int calibration_layouts = 100;  // choices whose finalists are replayed
  int executions = 4;             // replays of each finalist
  std::uint64_t seed = 2026;
  int samples = 64;  // the choice's full-model executions per finalist
  int threads = 2;
  int shot_limit = 12;  // of a drill's one visit (nine balls and some fouls to spare)
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct CalibrationPoint {
  double predicted = 0.0;
  int executions = 0, potted = 0;
};

struct PolicyResult {
  std::string noise, policy;
  int games = 0, attempts = 0, pots = 0, fouls = 0, run_outs = 0, balls = 0;
  std::vector<double> decision_us;  // of every decision
};

struct GameBenchmarkResult {
  GameBenchmarkOptions options;
  std::vector<CalibrationPoint> calibration;
  std::vector<double> choice_us;  // calibration choices, ChooseShot on `threads` threads
  bool thread_count_independent = false;
  std::vector<PolicyResult> policies;
};

GameBenchmarkResult RunGameBenchmark(const GameBenchmarkOptions& options);

// Writes game_report.md, game_reliability.png and game_results.json into `dir`.
void WriteGameReport(const GameBenchmarkResult& result, const std::string& dir);

// The headline numbers, as `bench-game` prints them.
nlohmann::json GameSummaryJson(const GameBenchmarkResult& result);

}  // namespace billiard::bench
