// The planner's benchmark: seeded random requests (planner/testing/request_suite.h) planned three
// ways (closed form alone; refined with the sensitivity Jacobian; refined with central
// differences), every plan re-simulated independently at the simulator's default tolerance, timed
// on one core.
#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner/shot_planner.h"
#include "sim/physics/parameters.h"

namespace billiard::bench {

struct PlannerVariant {
  std::string name;  // "closed-form", "refined/sensitivities", "refined/central-differences"
  planner::PlannerOptions options;
};

std::vector<PlannerVariant> PlannerVariants();

struct PlannerRun {
  std::string variant;
  int request = 0;  // index in the suite
  planner::ShotRequest shot;
  planner::ShotPlan plan;
  // Miss of the plan's launch re-simulated (approx model, RODAS4, tolerance 1e-7, tighter than
  // the planner's own), where the speed falls to the final speed; -1 when the plan is not ok.
  double verified_miss_m = -1.0;
};

struct PlannerBenchmarkOptions {
  int requests = 500;
  std::uint32_t seed = 2026;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
};

struct PlannerBenchmarkResult {
  std::string params;
  int requests = 0;
  std::uint32_t seed = 0;
  std::vector<PlannerRun> runs;
  double wall_s = 0.0;
};

PlannerBenchmarkResult RunPlannerBenchmark(const physics::ModelParameters& p,
                                           const PlannerBenchmarkOptions& options);

// Writes planner_report.md and planner_results.csv into `dir` (created if missing).
void WritePlannerReport(const PlannerBenchmarkResult& result, const std::string& dir);

// One JSON object summarising the run, for stdout.
nlohmann::json PlannerSummaryJson(const PlannerBenchmarkResult& result);

}  // namespace billiard::bench
