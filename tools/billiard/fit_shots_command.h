#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard fit-shots`: the cue strikes, and the shared physics constants, that reproduce tracked
// shots through the whole-table simulation (docs/identification.md).
void AddFitShotsCommand(CLI::App& app);

}  // namespace billiard::cli
