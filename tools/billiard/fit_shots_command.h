#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard fit-shots`: the cue strikes, and the shared physics constants, that reproduce tracked
// shots through the whole-table simulation (docs/identification.md).
void AddFitShotsCommand(CLI::App& app);

// `billiard identify`: the same joint fit from a recorded run of the loop, its commanded strikes
// and the estimator's tracks (docs/identification.md).
void AddIdentifyCommand(CLI::App& app);

// `billiard bench-shot-fit`: the constants hidden, shots simulated and tracked with them, and
// recovered by the same fit (docs/identification.md).
void AddBenchShotFitCommand(CLI::App& app);

}  // namespace billiard::cli
