#include "tools/billiard/edge_report_command.h"

#include <iostream>

#include "planner/edge_report.h"

namespace billiard::cli {

void AddEdgeReportCommand(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "edge-report",
      "Simulate and plan with contact parameters at their edges (mu = 0, d = 0, eps = 1e-9, "
      "too small budgets) and print the measurements as JSON");
  cmd->callback([] {
    std::cerr << "edge-report: about a second" << std::endl;
    std::cout << planner::EdgeParameterReport().dump() << std::endl;
  });
}

}  // namespace billiard::cli
