#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

// billiard bench [--quick] --out DIR: the speed-against-error benchmark (bench/).
void AddBenchCommand(CLI::App& app);

}  // namespace billiard::cli
