// Frames of a video file, through OpenCV's VideoCapture with its FFmpeg backend (any backend
// OpenCV finds, GStreamer's among them, in a build without FFmpeg).
//
// A frame's capture time is the time of the opening plus the frame's own time in the video
// (CAP_PROP_POS_MSEC, its presentation time; its index over the rate where a backend gives
// none), so that the estimator sees the recording's speeds whatever pace the node plays it at.
//
// The end of a video is told from a cut: a container that announces its frame count (AVI's
// header, MP4's index) and ends before it was cut short, which is a failure, not an end. A file
// that no backend opens, or that opens but has no frame that decodes, fails too. (A video cut
// inside a frame can hand over that last frame damaged, with what the codec could not decode
// left grey: FFmpeg decodes what it has without saying so to OpenCV.)
//
// Module: billiard::camera_node.
#pragma once

#include <cstdint>
#include <string>

#include <opencv2/videoio.hpp>

#include "tools/camera_node/frame_source.h"

namespace billiard::camera_node {

class VideoFileSource : public FrameSource {
 public:
  explicit VideoFileSource(std::string path);

  std::string Describe() const override { return "the video '" + path_ + "'"; }
  std::string Open() override;
  ReadResult Read() override;
  // Back to the first frame, the capture times going on one frame interval after the last.
  bool Restart() override;
  double FrameRate() const override { return rate_; }
  bool Live() const override { return false; }

 private:
  // The capture time of the frame just read, the `index`th of this pass.
  std::int64_t CaptureUtime(long index) const;
  ReadResult Ended() const;

  const std::string path_;
  cv::VideoCapture capture_;
  double rate_ = 0.0;        // [Hz], 0 when the file says none
  long announced_ = 0;       // the frames the container announces, 0 when it does not
  long read_ = 0;            // frames read in this pass
  std::int64_t origin_ = 0;  // the capture time of the pass's time 0 [us]
  std::int64_t last_utime_ = 0;
};

}  // namespace billiard::camera_node
