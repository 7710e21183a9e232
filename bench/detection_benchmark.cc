#include "bench/detection_benchmark.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "bench/format.h"
#include "bench/one_thread.h"
#include "estimator/detection_overlay.h"

namespace billiard::bench {

namespace {

template <class Run>
double MillisecondsOf(const Run& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

std::string Stem(const std::string& file) { return std::filesystem::path(file).stem().string(); }

}  // namespace

double Median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

DetectionBenchmarkResult RunDetectionBenchmark(const std::string& set,
                                               const std::vector<LabelledFrame>& frames,
                                               const DetectionBenchmarkOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const OneThread one_thread;
  DetectionBenchmarkResult result;
  result.set = set;
  if (!options.overlay_dir.empty()) std::filesystem::create_directories(options.overlay_dir);
  for (const LabelledFrame& frame : frames) {
    const cv::Mat image =
        frame.image.empty() ? options.read_image(set + "/" + frame.file) : frame.image;
    estimator::DetectorOptions detector_options;
    detector_options.ball_set = BallSetFor(frame);
    detector_options.identity.classifier = options.classifier;
    estimator::BallDetector detector(detector_options);
    std::vector<estimator::BallDetection> balls;
    const double first_ms = MillisecondsOf([&] { balls = detector.Detect(image); });
    std::vector<double> next_ms;
    for (int i = 0; i < kNextFrameRepeats; ++i) {
      next_ms.push_back(MillisecondsOf([&] { detector.Detect(image); }));
    }
    FrameScore score = ScoreFrame(frame, balls);
    score.size = image.size();
    score.first_frame_ms = first_ms;
    score.next_frame_ms = Median(next_ms);
    score.failure = detector.failure();
    if (detector.knows_table()) score.table = detector.table();
    score.table_view = score.table ? estimator::TableViewName(score.table->view) : "";
    score.view = !frame.view.empty() ? frame.view : score.table_view;
    score.table_labelled = frame.corners.has_value();
    if (frame.corners && score.table) {
      score.table_side_error_px = TableSideError(frame, *score.table, image.size());
    }
    ExplainMisses(frame, &score);
    if (!options.overlay_dir.empty()) {
      const std::string path = options.overlay_dir + "/" + Stem(frame.file) + ".jpg";
      if (!cv::imwrite(path, ScoreOverlay(image, frame, score))) {
        throw std::runtime_error("cannot write '" + path + "'");
      }
    }
    options.progress(frame.file + ": " + std::to_string(score.found) + " of " +
                     std::to_string(score.labels) + " found, " +
                     std::to_string(score.false_detections) + " false" +
                     (score.table_side_error_px >= 0
                          ? ", table " + Fixed(score.table_side_error_px, 1) + " px"
                          : std::string()) +
                     ", " + Fixed(first_ms, 1) +
                     " ms" + (score.failure.empty() ? "" : " (" + score.failure + ")"));
    result.frames.push_back(std::move(score));
  }
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

cv::Mat ScoreOverlay(const cv::Mat& image, const LabelledFrame& frame, const FrameScore& score) {
  cv::Mat out = image.clone();
  if (score.table) estimator::DrawTable(*score.table, &out);
  const double gate = MatchDistancePx(frame.radius_px);
  const auto point = [](const Eigen::Vector2d& p) {
    return cv::Point(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
  };
  const int thickness = std::max(1, static_cast<int>(frame.radius_px / 8));
  for (const auto& p : frame.ignored) {
    cv::circle(out, point(p), static_cast<int>(gate), {160, 160, 160}, thickness);
  }
  for (const auto& p : score.missed) {
    cv::circle(out, point(p), static_cast<int>(frame.radius_px + 3), {0, 255, 255}, 2 * thickness);
  }
  for (std::size_t i = 0; i < score.detections.size(); ++i) {
    const auto& d = score.detections[i];
    const cv::Scalar colour =
        score.detection_matched[i] ? cv::Scalar(0, 255, 0) : cv::Scalar(0, 0, 255);
    cv::circle(out, point(d.pixel), static_cast<int>(std::lround(d.radius_px)), colour, thickness);
    cv::drawMarker(out, point(d.pixel), colour, cv::MARKER_CROSS, 5, 1);
  }
  for (const auto& p : frame.balls)
    cv::drawMarker(out, point(p), {255, 0, 255}, cv::MARKER_TILTED_CROSS, 5, 1);
  return out;
}

}  // namespace billiard::bench
