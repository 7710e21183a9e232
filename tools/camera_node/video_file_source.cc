#include "tools/camera_node/video_file_source.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <opencv2/videoio/registry.hpp>

namespace billiard::camera_node {

namespace {

// Frames that a container's count may announce beyond those it holds without the file being
// cut: some (Matroska, some MP4s) estimate the count from the duration and the rate, rounding up.
constexpr long kFrameCountSlack = 1;

// A property of `capture` when it is a finite positive number, else 0.
double PositiveProperty(const cv::VideoCapture& capture, int property) {
  const double value = capture.get(property);
  return std::isfinite(value) && value > 0 ? value : 0.0;
}

// FFmpeg where the build has it: it reads every common container and codec, and says no
// quietly (GStreamer's backend, tried on a file that is no video, leaves GLib's criticals on
// stderr). Else whichever backend OpenCV finds.
cv::VideoCaptureAPIs FileBackend() {
  return cv::videoio_registry::hasBackend(cv::CAP_FFMPEG) ? cv::CAP_FFMPEG : cv::CAP_ANY;
}

// The backend a file was tried with, for the line that says it is no video.
std::string BackendName() { return FileBackend() == cv::CAP_ANY ? "any backend" : "FFmpeg"; }

}  // namespace

VideoFileSource::VideoFileSource(std::string path) : path_(std::move(path)) {}

std::string VideoFileSource::Open() {
  if (!capture_.open(path_, FileBackend())) {
    return Describe() + " is not a video that OpenCV reads (" + BackendName() + ")";
  }
  rate_ = PositiveProperty(capture_, cv::CAP_PROP_FPS);
  announced_ = std::lround(PositiveProperty(capture_, cv::CAP_PROP_FRAME_COUNT));
  origin_ = WallUtime();
  return "";
}

ReadResult VideoFileSource::Read() {
  ReadResult result;
  if (!capture_.read(result.frame.image) || result.frame.image.empty()) return Ended();
  result.kind = ReadResult::Kind::kFrame;
  result.frame.utime = CaptureUtime(read_++);
  last_utime_ = result.frame.utime;
  return result;
}

std::int64_t VideoFileSource::CaptureUtime(long index) const {
  const double rate = rate_ > 0 ? rate_ : kDefaultImageRate;
  const double position_ms = capture_.get(cv::CAP_PROP_POS_MSEC);
  // The backend's presentation time where it gives one (0 is only the first frame's).
  const bool positioned =
      std::isfinite(position_ms) && position_ms >= 0 && (position_ms > 0 || index == 0);
  const double since_origin_us = positioned ? 1e3 * position_ms : 1e6 * index / rate;
  // Strictly after the last frame, whatever the container says: the estimator ignores a
  // frame stamped as the one before it.
  return std::max<std::int64_t>(origin_ + std::llround(since_origin_us), last_utime_ + 1);
}

ReadResult VideoFileSource::Ended() const {
  ReadResult result;
  result.kind = ReadResult::Kind::kFailed;
  if (read_ == 0) {
    result.reason = Describe() + " has no frame that decodes";
  } else if (announced_ > read_ + kFrameCountSlack) {
    result.reason = Describe() + " ends after " + std::to_string(read_) + " of the " +
                    std::to_string(announced_) + " frames its header announces: it is cut short";
  } else {
    result.kind = ReadResult::Kind::kEnd;
    result.reason = Describe() + " ended after " + std::to_string(read_) + " frames";
  }
  return result;
}

bool VideoFileSource::Restart() {
  capture_.release();
  if (!capture_.open(path_, FileBackend())) return false;
  const double rate = rate_ > 0 ? rate_ : kDefaultImageRate;
  origin_ = last_utime_ + std::llround(1e6 / rate);
  read_ = 0;
  return true;
}

}  // namespace billiard::camera_node
