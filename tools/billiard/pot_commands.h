// The potting subcommands: `billiard plan-pot` (the stroke that pots a ball, planned against the
// whole-table simulation), `billiard bench-pot` (its truth, coverage, margin, throw, position
// and speed on seeded layouts) and `billiard pot-layout` (those layouts as scene files).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "planner/pot/pot_planner.h"

namespace billiard::cli {

// A plan as `plan-pot --json` prints it.
nlohmann::json PotPlanJson(const pot::PotPlan& plan);

void AddPlanPotCommand(CLI::App& app);
void AddBenchPotCommand(CLI::App& app);
// `billiard pot-layout`: bench-pot's seeded layouts as scene files (run_loop.sh --scene seeded).
void AddPotLayoutCommand(CLI::App& app);

}  // namespace billiard::cli
