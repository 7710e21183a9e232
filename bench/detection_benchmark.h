// The detector against labelled frames: real camera frames with hand or dataset labels (a
// directory with labels.json, as ../shared/data/real-tables/dev/), or the synthetic suite
// (rendered frames whose ball centres are known exactly). Recall, precision and centre error per
// frame, per view (overhead or oblique) and over all, with an overlay per frame.
// labels.json's format is labelled_set.h's; a frame is scored as frame_score.h says, and the
// figures over groups of frames and the report are detection_report.h's.
#pragma once

#include <functional>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "bench/frame_score.h"
#include "bench/labelled_set.h"
#include "estimator/ball_detector.h"

namespace billiard::bench {

// A next frame's time (FrameScore::next_frame_ms) is the median of this many.
inline constexpr int kNextFrameRepeats = 3;

// The middle of `values` (the upper of the two middle ones for an even count; 0 for none).
double Median(std::vector<double> values);

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

}  // namespace billiard::bench
