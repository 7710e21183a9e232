// The benchmark's outputs: report.md (tables and the targets), results.csv (one row per method
// and scene), speed_vs_error.png (log-log, one curve per method family) and model_choice.json
// (the table `billiard simulate --model auto` chooses from).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "bench/speed_error.h"

namespace billiard::bench {

// Writes the four files into `dir` (created if missing). Throws std::runtime_error on I/O errors.
void WriteReport(const BenchmarkResult& result, const std::string& dir);

// The per-kind summaries that the model choice reads.
nlohmann::json ModelChoiceTable(const BenchmarkResult& result);

// One JSON object summarising the run, for stdout.
nlohmann::json SummaryJson(const BenchmarkResult& result, const std::string& dir);

}  // namespace billiard::bench
