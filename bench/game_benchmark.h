// The shot choice's benchmark (planner/choice/), on seeded nine-ball layouts
// (game::SeededNineBallLayout) on the pool-9ft table:
//  - calibration: seeded choices (a seeded cue ball, nine-ball rules, the noise they plan for,
//    the table's own model), the chosen shot's reported probability (its confirmation, fresh
//    samples independent of the choice) against `executions` more plays of it with fresh noise
//    on the same model: the measured pot rate per decile of the prediction (a reliability
//    diagram). The replays execute with the plant's noise, by default the one the choice was
//    told; a plant noise it was not told shows as a miscalibration (issue 47: a noise learned
//    on the robot against the shipped guess);
//  - games: each layout a drill from ball in hand, one visit (until a shot pots nothing or
//    fouls), under the robot's noise and under the computational-pool noise, played by ours, by
//    ours without the lookahead and by the easiest-looking ghost-ball shot (the players of
//    planner/players/, each a game of planner/game/): pots per attempt,
//    run-outs, fouls. The layouts run in chunks, each layout's six drills side by side on the
//    pool's threads (one thread each), so that a run stopped early has played every policy on
//    the same layouts (`checkpoint` is told after each chunk);
//  - decision time: the calibration choices' wall time (our player's, no ball in hand, on all
//    the threads), and whether one thread and `threads` give the same choice.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <optional>
#include <vector>

#include "bench/calibration.h"
#include "planner/game/game.h"
#include "sim/params/execution_noise.h"

namespace billiard::bench {

struct GameBenchmarkOptions {
  int layouts = 500;              // drills per noise and policy
  int calibration_layouts = 400;  // choices whose chosen shot is replayed
  int executions = 8;             // replays of each chosen shot
  int confirm_samples = 256;      // the choice's fresh executions of the chosen shot
  std::uint64_t seed = 2026;
  int samples = 64;  // the choice's full-model executions per finalist
  int threads = 2;
  int shot_limit = 12;  // of a drill's one visit (nine balls and some fouls to spare)
  int chunk = 10;  // layouts between checkpoints
  // The robot whose cue plays every choice's strokes (PotOptions::robot); none: the level cue.
  std::optional<cue::Robot> robot;
  // The calibration's noises, each a name or a file (sim/params/noise/): the one the choices
  // plan for, and the one their chosen shots are replayed with (empty: `noise`). The drills
  // keep their two named noises.
  std::string noise = params::kDefaultNoise;
  std::string plant_noise;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct PolicyResult {
  std::string noise, policy;
  int games = 0, attempts = 0, pots = 0, fouls = 0, run_outs = 0, balls = 0;
  int likely_attempts = 0, likely_pots = 0;  // the attempts the choice called likely
  std::vector<double> decision_us;  // of every decision
};

struct GameBenchmarkResult {
  GameBenchmarkOptions options;
  std::vector<CalibrationPoint> calibration;
  std::vector<double> choice_us;  // calibration choices, our player's on `threads` threads
  bool thread_count_independent = false;
  std::vector<PolicyResult> policies;
};

// `checkpoint` is told the result so far after the calibration and after each chunk of layouts.
GameBenchmarkResult RunGameBenchmark(
    const GameBenchmarkOptions& options,
    const std::function<void(const GameBenchmarkResult&)>& checkpoint = nullptr);

// Writes game_report.md, game_reliability.png and game_results.json into `dir`.
void WriteGameReport(const GameBenchmarkResult& result, const std::string& dir);

// The headline numbers, as `bench-game` prints them.
nlohmann::json GameSummaryJson(const GameBenchmarkResult& result);

}  // namespace billiard::bench
