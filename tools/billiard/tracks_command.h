// `billiard tracks LOG`: the estimator's TABLE_STATE messages of a recorded run, track by track
// (JSON): what it saw of the table, as `run_loop.sh --camera` prints it after a camera or a
// video has been played through the estimator.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddTracksCommand(CLI::App& app);

}  // namespace billiard::cli
