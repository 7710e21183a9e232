// build/bin/planner_node's command line: its options, checked, and the node run with them until
// SIGINT or SIGTERM (planner_node_main.cc is the few lines that join them).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "planner/node/planner_node.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/robots.h"
#include "sim/params/table_specs.h"

namespace billiard::planner_node {

struct PlannerNodeCommandLine {
  std::string lcm_url;  // empty: $LCM_DEFAULT_URL, else LCM's default
  std::string params = params::kDefaultParameterSet;
  std::string table = params::kDefaultTable;  // a built-in table or a table file (table_specs.h)
  std::string robot = params::kDefaultRobot;  // --robot: a built-in robot or a robot file (robots.h)
  PlannerNodeOptions options;
  bool no_refine = false;
  std::string identify = "mu,rolling";  // --identify: the constants an online fit identifies
};

// Adds the node's options to `app`, filling `line` when it parses.
void AddPlannerNodeOptions(CLI::App& app, PlannerNodeCommandLine* line);

// The node's options from a parsed command line, with `params`; throws std::invalid_argument
// with a one-line reason when they make no node (a negative or non-finite limit, an empty queue,
// a table that does not load or is not the size of the parameter set's, a negative
// --identify-every, an unknown constant in --identify, a --robot that does not load).
PlannerNodeOptions NodeOptions(const PlannerNodeCommandLine& line,
                               const physics::ModelParameters& params);

// Runs the node: 2 for options or parameters that make no node (the reason on stderr), else the
// status of nodes::RunNodeUntilStopped.
int RunPlannerNodeCommand(const PlannerNodeCommandLine& line);

}  // namespace billiard::planner_node
