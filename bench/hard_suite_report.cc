#include "bench/hard_suite_report.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "bench/detection_report.h"
#include "bench/format.h"

namespace billiard::bench {

namespace {

// The cases in the order the suite renders them, each with its frames' indices.
std::vector<std::pair<std::string, std::vector<std::size_t>>> ByCondition(
    const HardSuiteResult& result) {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> cases;
  for (std::size_t i = 0; i < result.conditions.size(); ++i) {
    if (cases.empty() || cases.back().first != result.conditions[i]) {
      cases.push_back({result.conditions[i], {}});
    }
    cases.back().second.push_back(i);
  }
  return cases;
}

double WorstSide(const std::array<double, 4>& errors) {
  return *std::max_element(errors.begin(), errors.end());
}

double MedianOf(std::vector<double> values) {
  if (values.empty()) return -1;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

nlohmann::json CaseJson(const HardSuiteResult& result, const std::vector<std::size_t>& frames) {
  std::vector<const FrameScore*> scores;
  std::vector<double> worst, seen;
  int within = 0, found = 0;
  for (const std::size_t i : frames) {
    scores.push_back(&result.detection.frames[i]);
    seen.push_back(result.seen_shares[i]);
    within += SidesWithin(result, i);
    if (!result.detection.frames[i].table) continue;
    ++found;
    worst.push_back(WorstSide(result.side_errors_px[i]));
  }
  const Totals t = Total(scores);
  return {{"frames", frames.size()},
          {"tables_found", found},
          {"tables_within_tolerance", within},
          {"tolerance_px", result.tolerances_px[frames.front()]},
          {"worst_side_error_px", worst.empty() ? -1 : *std::max_element(worst.begin(), worst.end())},
          {"median_worst_side_error_px", MedianOf(worst)},
          {"recall", t.recall},
          {"precision", t.precision},
          {"labels", t.labels},
          {"found", t.found},
          {"false", t.false_detections},
          {"median_seen_share", MedianOf(seen)}};
}

std::string SideCell(double e) { return e < 0 ? "out" : Fixed(e, 1); }

}  // namespace

bool SidesWithin(const HardSuiteResult& result, std::size_t frame) {
  if (!result.detection.frames[frame].table) return false;
  return WorstSide(result.side_errors_px[frame]) <= result.tolerances_px[frame];
}

HardSuiteResult RunHardSuite(const std::vector<HardFrame>& frames,
                             const DetectionBenchmarkOptions& options) {
  std::vector<LabelledFrame> labelled;
  for (const HardFrame& f : frames) labelled.push_back(f.frame);
  HardSuiteResult result;
  result.detection = RunDetectionBenchmark("hard suite", labelled, options);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto& table = result.detection.frames[i].table;
    result.side_errors_px.push_back(table ? SideErrorsPx(frames[i], *table)
                                          : std::array<double, 4>{-1, -1, -1, -1});
    result.conditions.push_back(frames[i].condition);
    result.seen_shares.push_back(frames[i].seen_share);
    result.tolerances_px.push_back(frames[i].tolerance_px);
  }
  return result;
}

nlohmann::json HardSuiteJson(const HardSuiteResult& result) {
  nlohmann::json cases = nlohmann::json::object();
  for (const auto& [condition, frames] : ByCondition(result)) {
    cases[condition] = CaseJson(result, frames);
  }
  return {{"suite", "hard"}, {"frames", result.conditions.size()}, {"cases", cases}};
}

void WriteHardSuiteReport(const HardSuiteResult& result, const std::string& dir) {
  nlohmann::json all = HardSuiteJson(result);
  nlohmann::json frames = nlohmann::json::array();
  for (std::size_t i = 0; i < result.conditions.size(); ++i) {
    const FrameScore& f = result.detection.frames[i];
    frames.push_back({{"file", f.file},
                      {"condition", result.conditions[i]},
                      {"side_errors_px", result.side_errors_px[i]},
                      {"sides_within_tolerance", SidesWithin(result, i)},
                      {"seen_share", result.seen_shares[i]},
                      {"labels", f.labels},
                      {"found", f.found},
                      {"false", f.false_detections},
                      {"failure", f.failure}});
  }
  all["frame_scores"] = frames;
  OpenForWriting(dir + "/hard_suite_results.json") << all.dump(1) << "\n";

  std::ofstream md = OpenForWriting(dir + "/hard_suite_report.md");
  md << "# The detector on the rendered hard suite\n\n"
     << "`billiard bench-detect --hard-suite` (bench/hard_suite.h): the cases that lose real "
     << "tables, rendered with their truth. A side's error is the largest distance of its true "
     << "edge (the foot of the cushion's face where the camera sees the face, its nose where the "
     << "camera is beyond it; projected by the camera, lens included, where it is in the frame) "
     << "from the found side (its line, or through the lens the finder estimated the curve that "
     << "is its image); a table is within tolerance when every side in the frame is (2 px, "
     << "3 px under k1 = -0.3). Balls less than half seen (behind an arm, a player or another "
     << "ball) are ignored.\n\n"
     << "| case | frames | seen share | tables found | within tolerance | worst side [px] | "
        "median worst side [px] | recall | precision |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [condition, group] : ByCondition(result)) {
    const nlohmann::json c = CaseJson(result, group);
    md << "| " << condition << " | " << c["frames"] << " | "
       << Fixed(100 * c["median_seen_share"].get<double>(), 0) << " % | " << c["tables_found"]
       << " | " << c["tables_within_tolerance"] << " (" << Fixed(c["tolerance_px"], 0) << " px) | "
       << SideCell(c["worst_side_error_px"]) << " | " << SideCell(c["median_worst_side_error_px"])
       << " | " << Fixed(100 * c["recall"].get<double>(), 1) << " % | "
       << Fixed(100 * c["precision"].get<double>(), 1) << " % |\n";
  }
  md << "\n| frame | sides 0-3 [px] | seen | found / labels | false | note |\n"
        "|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < result.conditions.size(); ++i) {
    const FrameScore& f = result.detection.frames[i];
    md << "| " << f.file << " | ";
    for (int k = 0; k < 4; ++k) {
      md << (f.table ? SideCell(result.side_errors_px[i][k]) : std::string("-"))
         << (k < 3 ? ", " : "");
    }
    md << " | " << Fixed(100 * result.seen_shares[i], 0) << " % | " << f.found << " / "
       << f.labels << " | " << f.false_detections << " | " << f.failure << " |\n";
  }
  if (!md) throw std::runtime_error("writing the hard suite report failed");
}

}  // namespace billiard::bench
