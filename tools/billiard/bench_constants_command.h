// `billiard bench-constants`: issue 47's calibration of banks and kicks on tables whose
// constants are drawn from the parameter set's uncertainty (bench/constants_calibration.h); the
// summary as JSON on stdout, with --out constants_report.md and constants_results.json.
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchConstantsCommand(CLI::App& app);

}  // namespace billiard::cli
