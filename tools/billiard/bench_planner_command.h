// `billiard bench-planner`: the planner's solve time and misses over seeded random requests.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchPlannerCommand(CLI::App& app);

}  // namespace billiard::cli
