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
#pragma once

#include <Eigen/Core>
#include <functional>
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
  cv::Mat image;  // the frame, when not read from `file`
};

// The frames of a labelled set, in the order of labels.json. Throws std::invalid_argument with a
// one-line reason naming the file and the entry when labels.json is missing or malformed.
std::vector<LabelledFrame> LoadLabelledSet(const std::string& directory);

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
  std::optional<estimator::TableRegion> table;
};

// Detections scored against a frame's labels.
FrameScore ScoreFrame(const LabelledFrame& frame,
                      const std::vector<estimator::BallDetection>& detections);

struct DetectionBenchmarkOptions {
  // Reads an image file (BGR); throws std::invalid_argument with the reason when it cannot.
  std::function<cv::Mat(const std::string&)> read_image;
  // Where to write an overlay per frame ("" for none).
  std::string overlay_dir;
  std::function<void(const std::string&)> progress = [](const std::string&) {};
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
  double recall = 0, precision = 0, median_error_px = 0;
  double median_first_frame_ms = 0, median_next_frame_ms = 0;
};
Totals Total(const std::vector<const FrameScore*>& frames);

// detection_report.md (and detection_results.json) into `dir`, created if missing.
void WriteDetectionReport(const DetectionBenchmarkResult& result, const std::string& dir);

nlohmann::json DetectionSummaryJson(const DetectionBenchmarkResult& result);

}  // namespace billiard::bench
