// The choice of a source from the command line's words: a missing path is refused before
// anything opens, a number names a V4L2 device, a pipeline is left to GStreamer.
#include "tools/camera_node/frame_source.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node {
namespace {

std::string Refusal(const SourceSpec& spec) {
  try {
    MakeFrameSource(spec);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(FrameSource, PathsThatAreNotThereAreRefusedInOneLine) {
  EXPECT_EQ(Refusal({SourceSpec::Kind::kVideo, "/no/such.avi"}), "no video file at '/no/such.avi'");
  EXPECT_EQ(Refusal({SourceSpec::Kind::kVideo, ::testing::TempDir()}),
            "no video file at '" + ::testing::TempDir() + "'");
  EXPECT_EQ(Refusal({SourceSpec::Kind::kImages, "/no/such/dir"}),
            "no directory of images at '/no/such/dir'");
  EXPECT_EQ(Refusal({SourceSpec::Kind::kDevice, "/dev/no_such_video"}),
            "no camera at '/dev/no_such_video'");
  // A number is the V4L2 device of that number.
  EXPECT_EQ(Refusal({SourceSpec::Kind::kDevice, "97"}), "no camera at '/dev/video97'");
}

TEST(FrameSource, EachKindMakesItsSource) {
  const std::string video = ::testing::TempDir() + "/frame_source_video.avi";
  testing::WriteMjpgVideo(video, testing::NumberedFrames(2, cv::Size(64, 32)), 10.0);
  EXPECT_EQ(MakeFrameSource({SourceSpec::Kind::kVideo, video})->Describe(),
            "the video '" + video + "'");
  EXPECT_EQ(MakeFrameSource({SourceSpec::Kind::kImages, ::testing::TempDir()})->Describe(),
            "the images in '" + ::testing::TempDir() + "'");
  // A pipeline is GStreamer's to find or not, when it opens.
  const auto pipeline = MakeFrameSource({SourceSpec::Kind::kDevice, "no_such_element ! appsink"});
  EXPECT_EQ(pipeline->Describe(), "the GStreamer pipeline 'no_such_element ! appsink'");
  EXPECT_TRUE(pipeline->Live());
}

TEST(FrameSource, TheImagesRateIsTheCommandLinesOrThirtyHertz) {
  EXPECT_DOUBLE_EQ(MakeFrameSource({SourceSpec::Kind::kImages, ::testing::TempDir()})->FrameRate(),
                   kDefaultImageRate);
  SourceSpec slow{SourceSpec::Kind::kImages, ::testing::TempDir()};
  slow.fps = 2.5;
  EXPECT_DOUBLE_EQ(MakeFrameSource(slow)->FrameRate(), 2.5);
}

TEST(FrameSource, CaptureTimesAreTheEpochsMicroseconds) {
  const auto now = std::chrono::duration_cast<std::chrono::microseconds>(
                       std::chrono::system_clock::now().time_since_epoch())
                       .count();
  EXPECT_NEAR(static_cast<double>(WallUtime()), static_cast<double>(now), 1e5);
}

}  // namespace
}  // namespace billiard::camera_node
