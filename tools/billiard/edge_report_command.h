// `billiard edge-report`: the simulator and the planner at the edges of the contact parameters
// (planner/edge_report.h), as JSON on stdout.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddEdgeReportCommand(CLI::App& app);

}  // namespace billiard::cli
