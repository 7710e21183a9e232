// Frames of a live camera through OpenCV's VideoCapture: a V4L2 device (/dev/videoN) through
// its V4L2 backend, or a GStreamer pipeline ending in appsink through its GStreamer backend,
// where the build has it ("v4l2src device=/dev/video0 ! videoconvert ! appsink": any text with
// a '!'), for a camera V4L2 does not drive or a stream over the network.
//
// A frame is stamped with the wall clock when the camera hands it over (grab), before it is
// decoded (retrieve): later than its exposure by the driver's and the USB link's latency, which
// OpenCV does not report in the epoch's clock. A read that gets no frame is kNoFrame and is
// read again: a camera that stops for good is told by FrameReader's watchdog, a camera that
// never answers too, since its read never returns.
//
// Module: billiard::camera_node.
#pragma once

#include <string>

#include <opencv2/videoio.hpp>

#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

// Whether `device` is a GStreamer pipeline rather than a device path: it has a '!'.
bool IsGStreamerPipeline(const std::string& device);

class CameraSource : public FrameSource {
 public:
  // `device`: a device path or a pipeline; `fps`, `width`, `height` are asked of a device when
  // positive (a pipeline says its own in its caps).
  CameraSource(std::string device, double fps, int width, int height);

  std::string Describe() const override;
  std::string Open() override;
  ReadResult Read() override;
  double FrameRate() const override { return rate_; }
  bool Live() const override { return true; }

 private:
  bool IsPipeline() const { return IsGStreamerPipeline(device_); }
  // Asks the open device for the rate and size the command line gave.
  void AskForTheFormat();

  const std::string device_;
  const double fps_;
  const int width_, height_;
  cv::VideoCapture capture_;
  double rate_ = 0.0;
};

}  // namespace billiard::camera_node
