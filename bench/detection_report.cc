#include "bench/detection_report.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "bench/format.h"

namespace billiard::bench {

Totals Total(const std::vector<const FrameScore*>& frames) {
  Totals t;
  std::vector<double> errors, first_ms, next_ms;
  for (const FrameScore* f : frames) {
    ++t.frames;
    t.labels += f->labels;
    t.found += f->found;
    t.false_detections += f->false_detections;
    errors.insert(errors.end(), f->centre_errors.begin(), f->centre_errors.end());
    first_ms.push_back(f->first_frame_ms);
    next_ms.push_back(f->next_frame_ms);
    t.tables_labelled += f->table_labelled;
    t.tables_found += f->table_side_error_px >= 0 && f->table_side_error_px <= kTableSideTolerancePx;
    t.classed += f->classed;
    t.classed_right += f->classed_right;
    for (const auto& c : f->missed_causes) ++t.missed_by_cause[c];
    for (const auto& c : f->false_causes) ++t.false_by_cause[c];
  }
  t.recall = t.labels ? static_cast<double>(t.found) / t.labels : 0;
  t.precision = t.found + t.false_detections
                    ? static_cast<double>(t.found) / (t.found + t.false_detections)
                    : 0;
  t.median_error_px = Median(errors);
  t.median_first_frame_ms = Median(first_ms);
  t.median_next_frame_ms = Median(next_ms);
  return t;
}

std::map<std::string, std::vector<const FrameScore*>> ByView(
    const std::vector<FrameScore>& frames) {
  std::map<std::string, std::vector<const FrameScore*>> groups;
  for (const FrameScore& f : frames) {
    groups[f.view.empty() ? "no table" : f.view].push_back(&f);
    groups["all"].push_back(&f);
  }
  return groups;
}

nlohmann::json FiguresJson(const Totals& t) {
  return {{"frames", t.frames},
          {"labels", t.labels},
          {"found", t.found},
          {"false", t.false_detections},
          {"recall", t.recall},
          {"precision", t.precision},
          {"classed", t.classed},
          {"classed_right", t.classed_right},
          {"identity", t.classed ? static_cast<double>(t.classed_right) / t.classed : 0.0}};
}

namespace {

nlohmann::json TotalsJson(const Totals& t) {
  nlohmann::json j = FiguresJson(t);
  j.update({{"median_centre_error_px", t.median_error_px},
            {"median_first_frame_ms", t.median_first_frame_ms},
            {"median_next_frame_ms", t.median_next_frame_ms},
            {"tables_labelled", t.tables_labelled},
            {"tables_within_2px", t.tables_found},
            {"missed_by_cause", t.missed_by_cause},
            {"false_by_cause", t.false_by_cause}});
  return j;
}

}  // namespace

nlohmann::json DetectionSummaryJson(const DetectionBenchmarkResult& result) {
  nlohmann::json views = nlohmann::json::object();
  for (const auto& [view, frames] : ByView(result.frames)) views[view] = TotalsJson(Total(frames));
  return {{"set", result.set}, {"views", views}, {"wall_s", result.wall_s}};
}

void WriteDetectionReport(const DetectionBenchmarkResult& result, const std::string& dir) {
  std::filesystem::create_directories(dir);
  nlohmann::json frames = nlohmann::json::array();
  for (const FrameScore& f : result.frames) {
    nlohmann::json missed = nlohmann::json::array();
    for (const auto& p : f.missed) missed.push_back({p.x(), p.y()});
    frames.push_back({{"file", f.file},
                      {"view", f.view},
                      {"table_view", f.table_view},
                      {"labels", f.labels},
                      {"found", f.found},
                      {"false", f.false_detections},
                      {"median_centre_error_px", Median(f.centre_errors)},
                      {"width", f.size.width},
                      {"height", f.size.height},
                      {"first_frame_ms", f.first_frame_ms},
                      {"next_frame_ms", f.next_frame_ms},
                      {"missed", missed},
                      {"missed_causes", f.missed_causes},
                      {"false_causes", f.false_causes},
                      {"table_side_error_px", f.table_side_error_px},
                      {"table_within_2px", f.table_side_error_px >= 0 &&
                                               f.table_side_error_px <= kTableSideTolerancePx},
                      {"classed", f.classed},
                      {"classed_right", f.classed_right},
                      {"failure", f.failure}});
  }
  nlohmann::json all = DetectionSummaryJson(result);
  all["frames"] = frames;
  OpenForWriting(dir + "/detection_results.json") << all.dump(1) << "\n";

  std::ofstream md = OpenForWriting(dir + "/detection_report.md");
  md << "# Ball detection on a labelled set\n\n"
     << "`billiard bench-detect --set " << result.set << "`: every frame through the detector "
     << "from scratch (table, cloth, scale, balls), no radius given. A detection matches a label "
     << "within max(8 px, 0.6 R); balls labelled in a pocket or ignored count neither way. "
     << "Overlays: matched detections green, false ones red, missed labels yellow. Times are "
     << "wall time on one core: a camera's first frame (the table, the cloth and the scale "
     << "learnt, then the balls) and its next frames (the balls only, median of "
     << kNextFrameRepeats << ").\n\n"
     << "The table is found when every labelled side of the playing surface found is within "
     << Fixed(kTableSideTolerancePx, 0) << " px of the labelled side at both of its ends (corner "
     << "labels from `--corners`). Identity: the matched balls whose class is labelled, named "
     << "right (the ball set from the frame's `kind`).\n\n"
     << "| view | frames | labels | found | false | recall | precision | median centre error "
        "[px] | median time, first / next frame [ms] | tables within 2 px | identity |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& [view, group] : ByView(result.frames)) {
    const Totals t = Total(group);
    md << "| " << view << " | " << t.frames << " | " << t.labels << " | " << t.found << " | "
       << t.false_detections << " | " << Fixed(100 * t.recall, 1) << " % | "
       << Fixed(100 * t.precision, 1) << " % | " << Fixed(t.median_error_px, 2) << " | "
       << Fixed(t.median_first_frame_ms, 1) << " / " << Fixed(t.median_next_frame_ms, 1) << " | "
       << t.tables_found << " / " << t.tables_labelled << " | " << t.classed_right << " / "
       << t.classed << " |\n";
  }
  const Totals overall = Total(ByView(result.frames)["all"]);
  md << "\nMisses by cause:";
  for (const auto& [cause, n] : overall.missed_by_cause) md << " " << cause << " " << n << ";";
  md << "\nFalse detections by cause:";
  for (const auto& [cause, n] : overall.false_by_cause) md << " " << cause << " " << n << ";";
  md << "\n";
  md << "\n| frame | size | view (found) | labels | found | false | median error [px] | time, "
        "first / next frame [ms] | table side error [px] | identity | note |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const FrameScore& f : result.frames) {
    md << "| " << f.file << " | " << f.size.width << "x" << f.size.height << " | " << f.view
       << (f.table_view.empty() || f.table_view == f.view ? "" : " (" + f.table_view + ")") << " | "
       << f.labels << " | " << f.found << " | " << f.false_detections << " | "
       << Fixed(Median(f.centre_errors), 2) << " | " << Fixed(f.first_frame_ms, 1) << " / "
       << Fixed(f.next_frame_ms, 1) << " | "
       << (f.table_side_error_px >= 0 ? Fixed(f.table_side_error_px, 1) : std::string("-"))
       << " | " << (f.classed ? std::to_string(f.classed_right) + " / " + std::to_string(f.classed)
                              : std::string("-"))
       << " | " << f.failure << " |\n";
  }
  if (!md) throw std::runtime_error("writing the detection report failed");
}

}  // namespace billiard::bench
