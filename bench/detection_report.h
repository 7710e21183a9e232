// The detection benchmark's figures over groups of frames (recall, precision, median centre
// error, the tables found, identity, misses and false detections by cause; by view and over all)
// and its report: detection_report.md, detection_results.json and the summary `billiard
// bench-detect` prints.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/detection_benchmark.h"
#include "bench/frame_score.h"

namespace billiard::bench {

// recall, precision, median centre error over a group of frames.
struct Totals {
  int frames = 0, labels = 0, found = 0, false_detections = 0;
  int tables_labelled = 0, tables_found = 0, classed = 0, classed_right = 0;
  double recall = 0, precision = 0, median_error_px = 0;
  double median_first_frame_ms = 0, median_next_frame_ms = 0;
  std::map<std::string, int> missed_by_cause, false_by_cause;
};
Totals Total(const std::vector<const FrameScore*>& frames);

// A group's counts, recall, precision and identity (the matched balls whose class is labelled,
// named right), as JSON.
nlohmann::json FiguresJson(const Totals& t);

// The frames by view ("overhead", "oblique", or "no table" where neither was labelled nor found)
// and all of them ("all").
std::map<std::string, std::vector<const FrameScore*>> ByView(const std::vector<FrameScore>& frames);

// detection_report.md (and detection_results.json) into `dir`, created if missing.
void WriteDetectionReport(const DetectionBenchmarkResult& result, const std::string& dir);

// The figures by view and the wall time, as `billiard bench-detect` prints them.
nlohmann::json DetectionSummaryJson(const DetectionBenchmarkResult& result);

}  // namespace billiard::bench
