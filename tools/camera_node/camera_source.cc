#include "tools/camera_node/camera_source.h"

#include <cmath>
#include <utility>

namespace billiard::camera_node {

CameraSource::CameraSource(std::string device, double fps, int width, int height)
    : device_(std::move(device)), fps_(fps), width_(width), height_(height) {}

bool IsGStreamerPipeline(const std::string& device) {
  return device.find('!') != std::string::npos;
}

std::string CameraSource::Describe() const {
  return IsPipeline() ? "the GStreamer pipeline '" + device_ + "'" : "the camera " + device_;
}

std::string CameraSource::Open() {
  if (!capture_.open(device_, IsPipeline() ? cv::CAP_GSTREAMER : cv::CAP_V4L2)) {
    return IsPipeline() ? Describe() +
                              " does not start (are its elements installed? "
                              "gst-inspect-1.0 names them)"
                        : Describe() + " does not open as a V4L2 camera";
  }
  if (!IsPipeline()) AskForTheFormat();
  const double rate = capture_.get(cv::CAP_PROP_FPS);
  rate_ = std::isfinite(rate) && rate > 0 ? rate : 0.0;
  return "";
}

void CameraSource::AskForTheFormat() {
  if (width_ > 0) capture_.set(cv::CAP_PROP_FRAME_WIDTH, width_);
  if (height_ > 0) capture_.set(cv::CAP_PROP_FRAME_HEIGHT, height_);
  if (fps_ > 0) capture_.set(cv::CAP_PROP_FPS, fps_);
}

ReadResult CameraSource::Read() {
  ReadResult result;
  if (!capture_.grab()) return result;
  result.frame.utime = WallUtime();
  if (!capture_.retrieve(result.frame.image) || result.frame.image.empty()) {
    result.kind = ReadResult::Kind::kBadFrame;
    result.reason = Describe() + " handed over a frame that does not decode";
    return result;
  }
  result.kind = ReadResult::Kind::kFrame;
  return result;
}

}  // namespace billiard::camera_node
