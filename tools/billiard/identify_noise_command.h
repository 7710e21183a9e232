#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard identify-noise LOG`: the robot's execution noise (the spreads of its speed, heading
// and tip offsets, with their intervals) measured from a recorded run of the loop, each
// commanded stroke against the launch the estimator tracked (planner/node/noise_learning.h,
// docs/identification.md).
void AddIdentifyNoiseCommand(CLI::App& app);

}  // namespace billiard::cli
