// `billiard bench-detect`: the detector against a labelled set of frames
// (bench/detection_benchmark.h).
#pragma once

#include <CLI/CLI.hpp>

namespace billiard::cli {

void AddBenchDetectCommand(CLI::App& app);

}  // namespace billiard::cli
