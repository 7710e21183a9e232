// `billiard replay LOG`: a recorded closed-loop run through fresh estimator and planner nodes.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddReplayCommand(CLI::App& app);

}  // namespace billiard::cli
