#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// `billiard simulate`: one ball from an initial state to a given time, with any model.
void AddSimulateCommand(CLI::App& app);

}  // namespace billiard::cli
