// The detector against labelled frames: real camera frames with hand or dataset labels (a
// directory with labels.json, as ../shared/data/real-tables/dev/), or the synthetic suite
// (rendered frames whose ball centres are known exactly). Recall, precision and centre error per
// frame, per view (overhead or oblique) and over all, with an overlay per frame.
//
// labels.json: {"FILE": {"balls": [[u, v], ...], "ball_radius_px": R, "in_pocket": [[u, v]...],
// "ignore": [[u, v]...], "view": "overhead"|"oblique", "source": "...", ...}, "_...": notes}.
// `balls` must be found; `in_pocket` and `ignore` (balls in pockets, in hand, mostly hidden)
// count neither way; `view`, when given, files the frame under that view, else under the view the
// table finder sees. A detection matches a label within max(8 px, 0.6 R), one to one, nearest
// pairs first.
//
// Optional, per frame: `classes` (parallel to `balls`: "cue", "1".."15", "solid", "stripe",
// "eight", snooker's colours, carom's "white", "yellow", "red"; null where it cannot be told) and
// `kind` ("pool", "snooker", "carom"), which choose the ball set and score identity; and, from a
// corners file (LoadTableCorners), the playing surface's four corners, which score the table.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <memory>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "estimator/ball_detector.h"

namespace billiard::bench {

struct LabelledFrame {
  std::string file;                      // relative to the set's directory
  std::vector<Eigen::Vector2d> balls;    // must be found [px]
  std::vector<Eigen::Vector2d> ignored;  // in a pocket, in hand, hidden [px]
  double radius_px = 0;                  // typical ball radius [px]
  std::string view;                      // "overhead", "oblique" or "" (not labelled)
  std::string source;
  std::vector<std::string> classes;  // per ball, "" where not labelled
  std::string kind;                  // "pool", "snooker", "carom" or "" (not labelled)
  // The playing surface's corners in order around the table, and the side (corner k to k + 1)
  // that is out of the frame (-1: none).
  std::optional<std::array<Eigen::Vector2d, 4>> corners;
  int unseen_side = -1;
  cv::Mat image;  // the frame, when not read from `file`
};

// The frames of a labelled set, in the order of labels.json. Throws std::invalid_argument with a
// one-line reason naming the file and the entry when labels.json is missing or malformed.
std::vector<LabelledFrame> LoadLabelledSet(const std::string& directory);

// Adds the corner labels of `path` ({"FILE": {"corners": [[u, v] x 4], "unseen_side": k}, "_...":
// notes}) to the frames they name; frames it does not name keep none. Throws
// std::invalid_argument with a one-line reason when the file is missing or malformed.
void LoadTableCorners(const std::string& path, std::vector<LabelledFrame>* frames);

// A table is found when every labelled side of the playing surface found is within this of the
// labelled one at both of its ends (in the frame).
inline constexpr double kTableSideTolerancePx = 2.0;

// The detector's ball set for a frame's `kind` and labelled classes: carom and snooker by kind;
// pool by kind, unless its balls are labelled by colour (English pool's reds and yellows: the
// blackball set).
estimator::BallSet BallSetFor(const LabelledFrame& frame);

// Whether a detection's class is a labelled class: the same name, a number of that group for
// "solid" (1-7), "stripe" (9-15) and "eight", "cue" for carom's "white".
bool ClassMatches(const std::string& label, estimator::BallClass detected);

// How far a detection may be from its label [px].
double MatchDistancePx(double radius_px);

struct FrameScore {
  std::string file, view, table_view, source;
  std::string failure;  // why the detector found no table or no balls' scale, else ""
  int labels = 0, found = 0, false_detections = 0;
  std::vector<double> centre_errors;  // [px], of the matched labels
  cv::Size size;
  // On one core: the first frame (the table, the cloth and the scale learnt, then the balls) and
  // a next frame of the same camera (the balls only; the median of a few), wall time [ms].
  double first_frame_ms = 0, next_frame_ms = 0;
  std::vector<Eigen::Vector2d> missed;  // labels no detection matched
  std::vector<estimator::BallDetection> detections;
  std::vector<bool> detection_matched;  // per detection: a label's (or an ignored ball's)
  std::vector<int> detection_label;     // per detection: the label it matched, or -1
  std::optional<estimator::TableRegion> table;
  // Against the corner labels: the largest distance [px] of a found side from its labelled side
  // at the labelled side's ends in the frame (-1: no labels, or no table found).
  double table_side_error_px = -1;
  bool table_labelled = false;
  // Identity: matched balls whose class is labelled, and of those, named right.
  int classed = 0, classed_right = 0;
  // Why each label was missed and what each false detection was (MissCause, FalseCause).
  std::vector<std::string> missed_causes, false_causes;
};

// Why a label was missed: "no table" (none found), "outside the table found" (beyond the playing
// surface found), "by the cushion" (its centre within 1.5 R of a labelled side), "in a cluster"
// (within 2.5 R of another ball), else "on open cloth".
// What a false detection was: "duplicate" (within 2 R of a label another detection matched),
// "off the table" (outside the labelled playing surface), else "on the table" (a hand, a cue, a
// pocket, a mark).
void ExplainMisses(const LabelledFrame& frame, FrameScore* score);

// Detections scored against a frame's labels.
FrameScore ScoreFrame(const LabelledFrame& frame,
                      const std::vector<estimator::BallDetection>& detections);

struct DetectionBenchmarkOptions {
  // Reads an image file (BGR); throws std::invalid_argument with the reason when it cannot.
  std::function<cv::Mat(const std::string&)> read_image;
  // Where to write an overlay per frame ("" for none).
  std::string overlay_dir;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
  // The detector's identity classifier (`--identity model`); none, its rules.
  std::shared_ptr<const estimator::IdentityClassifier> classifier;
};

struct DetectionBenchmarkResult {
  std::string set;
  std::vector<FrameScore> frames;
  double wall_s = 0;
};

// The detector on every frame: its image, or the file `set`/`file` read with
// options.read_image, with OpenCV on one thread. `set` names the set in the report.
DetectionBenchmarkResult RunDetectionBenchmark(const std::string& set,
                                               const std::vector<LabelledFrame>& frames,
                                               const DetectionBenchmarkOptions& options);

// The frame with its labels and detections drawn: matched detections green, false ones red,
// missed labels yellow, ignored balls grey.
cv::Mat ScoreOverlay(const cv::Mat& image, const LabelledFrame& frame, const FrameScore& score);

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

nlohmann::json DetectionSummaryJson(const DetectionBenchmarkResult& result);

}  // namespace billiard::bench
