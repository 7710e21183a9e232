// `billiard bench-estimator`: the estimator's accuracy and speed on rendered shots.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchEstimatorCommand(CLI::App& app);

}  // namespace billiard::cli
