// build/bin/estimator_node's command line: its options, checked, and the node run with them until
// SIGINT or SIGTERM (estimator_node_main.cc is the few lines that join them).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "sim/params/parameter_sets.h"

namespace billiard::estimator_node {

struct EstimatorNodeCommandLine {
  std::string lcm_url;  // empty: $LCM_DEFAULT_URL, else LCM's default
  std::string params = params::kDefaultParameterSet;
  std::string camera;  // a camera model JSON file (billiard calibrate); empty: the overhead one
  std::string ball_model;  // the rig's look of its balls (billiard learn-balls); empty: hand-set
  std::string identity = "rules";  // "model": the built-in classifier (identity_classifier.h)
  int width = 1280, height = 720;  // of the overhead camera's frames [px]
};

// Adds the node's options to `app`, filling `line` when it parses.
void AddEstimatorNodeOptions(CLI::App& app, EstimatorNodeCommandLine* line);

// Runs the node: 2 for parameters, a camera or a ball model that do not load, or a ball model of
// another set than the parameters' balls (the reason on stderr), else the status of
// nodes::RunNodeUntilStopped.
int RunEstimatorNodeCommand(const EstimatorNodeCommandLine& line);

}  // namespace billiard::estimator_node
