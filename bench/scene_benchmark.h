// The table's benchmark: seeded 16-ball breaks (sim/table/testing/breaks.h) simulated event by
// event until every ball rests or is pocketed, timed on one core; events per break, cost per
// event, and the invariants every break must keep (no overlap, energy never rising).
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/physics/parameters.h"
#include "sim/table/table_geometry.h"
#include "sim/table/table_simulation.h"

namespace billiard::bench {

struct SceneBenchmarkOptions {
  int breaks = 200;
  std::uint64_t seed = 2026;
  double speed = 7.0;  // the cue ball's launch speed [m/s]
  int repeats = 5;     // each break timed this often, the fastest kept (timer noise)
  table::TableSimulationOptions simulation;
  std::string motion_model = "closed-form";  // what simulation.five_dof chooses, for the report
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct BreakRun {
  std::uint64_t seed = 0;
  double wall_us = 0.0;  // the fastest of the repeats, construction included
  int events = 0;
  int ball_ball = 0, cushion = 0, pocketed = 0, transitions = 0;  // events of each kind
  double duration_s = 0.0;  // simulated time until everything rests
};

struct SceneBenchmarkResult {
  std::string table, params;
  SceneBenchmarkOptions options;
  std::vector<BreakRun> runs;
  double wall_s = 0.0;
};

SceneBenchmarkResult RunSceneBenchmark(const table::TableGeometry& table,
                                       const physics::ModelParameters& p,
                                       const SceneBenchmarkOptions& options);

// Writes scenes_report.md into `dir` (created if missing): one table per run (per cushion model).
void WriteSceneReport(const std::vector<SceneBenchmarkResult>& runs, const std::string& dir);

// One JSON object summarising the run, for stdout.
nlohmann::json SceneSummaryJson(const SceneBenchmarkResult& result);

}  // namespace billiard::bench
