// A live camera: what is not a camera is refused in one line; where GStreamer has its test
// source, a pipeline's frames come stamped by the wall clock as they are handed over.
#include "tools/camera_node/camera_source.h"

#include <gtest/gtest.h>

#include <string>

namespace billiard::camera_node {
namespace {

TEST(CameraSource, WhatIsNotACameraIsRefusedInOneLine) {
  QuietVideoBackends();
  CameraSource not_a_camera("/dev/null", 0, 0, 0);
  EXPECT_TRUE(not_a_camera.Live());
  EXPECT_EQ(not_a_camera.Open(), "the camera /dev/null does not open as a V4L2 camera");
  CameraSource broken("no_such_element ! appsink", 0, 0, 0);
  EXPECT_EQ(broken.Open(),
            "the GStreamer pipeline 'no_such_element ! appsink' does not start (are its elements "
            "installed? gst-inspect-1.0 names them)");
}

TEST(CameraSource, APipelinesFramesAreStampedWhenHandedOver) {
  QuietVideoBackends();
  CameraSource pipeline(
      "videotestsrc num-buffers=5 ! video/x-raw,width=64,height=48,framerate=30/1 ! "
      "videoconvert ! appsink",
      0, 0, 0);
  if (!pipeline.Open().empty()) {
    GTEST_SKIP() << "GStreamer's videotestsrc, videoconvert or appsink is not installed "
                    "(gstreamer1.0-plugins-base)";
  }
  EXPECT_DOUBLE_EQ(pipeline.FrameRate(), 30.0);
  std::int64_t last = 0;
  for (int k = 0; k < 5; ++k) {
    const std::int64_t before = WallUtime();
    const ReadResult r = pipeline.Read();
    ASSERT_EQ(r.kind, ReadResult::Kind::kFrame) << "frame " << k << ": " << r.reason;
    EXPECT_EQ(r.frame.image.size(), cv::Size(64, 48));
    EXPECT_GE(r.frame.utime, before);
    EXPECT_LE(r.frame.utime, WallUtime());
    EXPECT_GT(r.frame.utime, last);
    last = r.frame.utime;
  }
  // The pipeline's end: no frame, which the reader's watchdog turns into a stall.
  EXPECT_EQ(pipeline.Read().kind, ReadResult::Kind::kNoFrame);
}

}  // namespace
}  // namespace billiard::camera_node
