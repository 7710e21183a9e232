#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard plan`: the stroke that sends a ball from one point to another (planner/shot_planner.h).
void AddPlanCommand(CLI::App& app);

}  // namespace billiard::cli
