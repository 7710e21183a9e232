// build/bin/planner_node's command line: its options, checked, and the node run with them until
// SIGINT or SIGTERM (planner_node_main.cc is the few lines that join them).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "planner/node/planner_node.h"
#include "sim/params/parameter_sets.h"

namespace billiard::planner_node {

struct PlannerNodeCommandLine {
  std::string lcm_url;  // empty: $LCM_DEFAULT_URL, else LCM's default
  std::string params = params::kDefaultParameterSet;
  PlannerNodeOptions options;
  bool no_refine = false;
};

// Adds the node's options to `app`, filling `line` when it parses.
void AddPlannerNodeOptions(CLI::App& app, PlannerNodeCommandLine* line);

// The node's options from a parsed command line; throws std::invalid_argument with a one-line
// reason when they make no node (a negative or non-finite limit, an empty queue).
PlannerNodeOptions NodeOptions(const PlannerNodeCommandLine& line);

// Runs the node: 2 for options or parameters that make no node (the reason on stderr), else the
// status of nodes::RunNodeUntilStopped.
int RunPlannerNodeCommand(const PlannerNodeCommandLine& line);

}  // namespace billiard::planner_node
