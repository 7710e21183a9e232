// build/bin/camera_node as a user runs it: a source that is not there is a usage error before
// anything opens; one that fails is one line and the node stays up until a signal, or exits 1
// with --exit-at-end; a whole video exits 0 with --exit-at-end.
#include "tools/camera_node/camera_node_command.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "tests/support/run_command.h"
#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node {
namespace {

using billiard::testing::RunCommandApart;
using billiard::testing::SeparateOutput;

const std::string kCameraNode = CAMERA_NODE_BIN;

int Lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

std::string Video(const std::string& name) {
  const std::string path = ::testing::TempDir() + "/camera_node_command_" + name;
  testing::WriteMjpgVideo(path, testing::NumberedFrames(20, cv::Size(96, 48)), 100.0);
  return path;
}

TEST(CameraNodeCommand, TheSourceIsTheOneOptionGiven) {
  CameraNodeCommandLine line;
  line.images = "frames/";
  line.fps = 12.5;
  SourceSpec spec = SourceOf(line);
  EXPECT_EQ(spec.kind, SourceSpec::Kind::kImages);
  EXPECT_EQ(spec.path, "frames/");
  EXPECT_DOUBLE_EQ(spec.fps, 12.5);
  line = {};
  line.device = "2";
  line.width = 640;
  line.height = 480;
  spec = SourceOf(line);
  EXPECT_EQ(spec.kind, SourceSpec::Kind::kDevice);
  EXPECT_EQ(spec.path, "2");
  EXPECT_EQ(spec.width, 640);
  EXPECT_EQ(spec.height, 480);
  line = {};
  line.video = "break.avi";
  EXPECT_EQ(SourceOf(line).kind, SourceSpec::Kind::kVideo);
}

TEST(CameraNodeCommand, ASourceThatIsNotThereOrNoneOrTwoAreUsageErrors) {
  for (const std::string& args :
       {std::string("--video /no/such.avi"), std::string("--images /no/such/dir"),
        std::string("--device /dev/no_such_camera"), std::string(""),
        "--video " + Video("two.avi") + " --images " + ::testing::TempDir(),
        "--images " + ::testing::TempDir() + " --fps 0",
        "--images " + ::testing::TempDir() + " --jpeg-quality 101"}) {
    const SeparateOutput r = RunCommandApart(kCameraNode + " " + args + " --lcm-url memq://");
    EXPECT_EQ(r.status, 2) << args << ": " << r.err;
    EXPECT_EQ(Lines(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("camera_node: ", 0), 0u) << r.err;
  }
}

TEST(CameraNodeCommand, WithExitAtEndAWholeVideoExitsZeroAndACutOneOne) {
  const std::string whole = Video("whole.avi");
  SeparateOutput r =
      RunCommandApart(kCameraNode + " --video " + whole + " --exit-at-end --lcm-url memq://");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "camera_node: the video '" + whole + "' is open, played at 100 Hz\n" +
                       "camera_node: the video '" + whole + "' ended after 20 frames\n");
  const std::string cut = ::testing::TempDir() + "/camera_node_command_cut.avi";
  testing::WriteCutShort(Video("to_cut.avi"), cut, 0.5);
  r = RunCommandApart(kCameraNode + " --video " + cut + " --exit-at-end --lcm-url memq://");
  EXPECT_EQ(r.status, 1) << r.err;
  ASSERT_EQ(Lines(r.err), 2) << r.err;
  EXPECT_NE(r.err.find("\ncamera_node: the video '" + cut + "' ends after "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("frames its header announces: it is cut short\n"), std::string::npos)
      << r.err;
}

TEST(CameraNodeCommand, AFileThatIsNoVideoIsOneLineAndTheNodeStaysUpUntilASignal) {
  const std::string garbage = ::testing::TempDir() + "/camera_node_command_garbage.avi";
  testing::WriteGarbage(garbage);
  // Still running a second later: the signal stops it, and it exits as a node does.
  const SeparateOutput r = RunCommandApart(
      kCameraNode + " --video " + garbage +
      " --lcm-url memq:// & pid=$!; sleep 1; kill -0 $pid && kill -TERM $pid; wait $pid");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "camera_node: the video '" + garbage +
                       "' is not a video that OpenCV reads (FFmpeg)\ncamera_node: stopped\n");
}

}  // namespace
}  // namespace billiard::camera_node
