// The detector on the hard suite (hard_suite.h) and its report: per case, each side's error
// against the truth (max over the side's length in the frame), whether every side is within the
// case's tolerance, recall and precision of the balls, and the share of the table in the frame.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/detection_benchmark.h"
#include "bench/hard_suite.h"

namespace billiard::bench {

struct HardSuiteResult {
  DetectionBenchmarkResult detection;  // the frames' scores, in the suite's order
  std::vector<std::string> conditions;
  std::vector<std::array<double, 4>> side_errors_px;  // per frame (-1: side out of frame)
  std::vector<double> seen_shares, tolerances_px;
};

// Whether a frame's table was found with every side in the frame within its tolerance.
bool SidesWithin(const HardSuiteResult& result, std::size_t frame);

// The detector on every frame of the suite (RunDetectionBenchmark), the sides scored.
HardSuiteResult RunHardSuite(const std::vector<HardFrame>& frames,
                             const DetectionBenchmarkOptions& options);

// Per case: frames, tables with every side within tolerance, the worst and median side error
// [px] of the tables found, recall and precision, the median share of the table in the frame.
nlohmann::json HardSuiteJson(const HardSuiteResult& result);

// hard_suite_report.md and hard_suite_results.json into `dir` (which must exist).
void WriteHardSuiteReport(const HardSuiteResult& result, const std::string& dir);

}  // namespace billiard::bench
