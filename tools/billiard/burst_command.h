// `billiard burst`: a burst of shot requests at a running planner_node over LCM, and what came
// back: every request answered or not, by status, the round-trip latency, and the planner's own
// NODE_STATUS. A planner that does not answer the probe, or a request, in time is an internal
// failure (exit 1): the burst measures a planner that answers everything.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBurstCommand(CLI::App& app);

}  // namespace billiard::cli
