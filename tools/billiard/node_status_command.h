// `billiard node-status LOG`: the NODE_STATUS messages of a recorded run, per node process: its
// last counts, its refusals, and the worst latency and queue it reported.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddNodeStatusCommand(CLI::App& app);

}  // namespace billiard::cli
