// The pot planner's benchmark (planner/pot/): seeded layouts (planner/pot/testing/pot_layouts.h)
// on pool and snooker tables, each pot planned on one core and every plan checked on its own
// against the table simulation `billiard simulate --scene` runs by default (the launch v0, w0 and
// the hop simulated from the scene, independently of the planner's own check):
//  - truth: every "ok" plan pots K in P, without a scratch or a foul first contact;
//  - coverage: of the pots whose straight ghost-ball line is clear, the share planned; what the
//    banks, kicks and curves make where it is blocked;
//  - margin: every heading on issue 47's grid (0.01 degree) inside the margin each side pots,
//    and the first past it misses;
//  - throw: the plans aimed through the ghost ball alone (throw not corrected), by cut angle;
//  - position: random cue-ball targets within 0.5 m of the object ball, how many are feasible
//    and how close the simulated rest is to them;
//  - speed: the wall time per plan.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "planner/pot/pot_planner.h"

namespace billiard::bench {

struct PotBenchmarkOptions {
  int layouts = 500;
  std::uint64_t seed = 2026;
  int margin_checks = 100;   // plans whose margin is checked
  int position_targets = 100;
  // Every snooker_every-th layout is on the snooker table (the rest pool-9ft).
  int snooker_every = 5;
  // The robot whose cue plays the plans (PotOptions::robot); none: the level cue, unchecked.
  std::optional<cue::Robot> robot;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct PotRun {
  std::uint64_t seed = 0;
  std::string table;
  int balls = 0;
  bool straight_clear = false;  // the straight ghost-ball line is clear and the cut below 80 deg
  pot::PotPlan plan;
  // The plan's CPU time on its thread [us]: what it costs one core, whatever else the machine
  // runs (plan.solve_us is the wall time).
  double cpu_us = 0.0;
  // The independent check of an ok plan (simulate --scene's default models).
  bool verified = false;
  std::string verify_failure;
  // The plan aimed through the ghost ball alone, simulated: whether it still pots (ok plans).
  std::optional<bool> ghost_pots;
  // The margin's checks (left, right): every heading of the grid inside it pots, the first past
  // it misses.
  std::optional<bool> inner_left, inner_right, outer_left, outer_right;
};

struct PositionRun {
  std::uint64_t seed = 0;
  Eigen::Vector2d target = Eigen::Vector2d::Zero();
  pot::PotPlan plan;
  double rest_error_m = -1.0;  // the simulated rest against the target, ok plans
  bool legal = false;          // the simulated shot pots legally
};

struct PotBenchmarkResult {
  PotBenchmarkOptions options;
  std::vector<PotRun> runs;
  std::vector<PositionRun> positions;
  double wall_s = 0.0;
};

PotBenchmarkResult RunPotBenchmark(const PotBenchmarkOptions& options);

// Writes pot_report.md and pot_results.csv (a row per layout and per target) into `dir`
// (created if missing).
void WritePotReport(const PotBenchmarkResult& result, const std::string& dir);

// One JSON object summarising the run, for stdout.
nlohmann::json PotSummaryJson(const PotBenchmarkResult& result);

}  // namespace billiard::bench
