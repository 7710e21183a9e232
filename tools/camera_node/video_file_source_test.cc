// A video file's frames: every one in order at its time in the video, the end told from a cut,
// a file that is no video refused in one line, and a second pass after the first.
#include "tools/camera_node/video_file_source.h"

#include <gtest/gtest.h>

#include <string>

#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node {
namespace {

constexpr int kFrames = 20;
constexpr double kRate = 25.0;  // [Hz]: frames 40 ms apart
const cv::Size kSize(160, 90);

std::string Video(const std::string& name) {
  const std::string path = ::testing::TempDir() + "/video_file_source_" + name;
  testing::WriteMjpgVideo(path, testing::NumberedFrames(kFrames, kSize), kRate);
  return path;
}

// Reads frames until the source gives anything else, which is returned; `frames` gets them.
ReadResult ReadAll(VideoFileSource& source, std::vector<CapturedFrame>* frames) {
  for (;;) {
    ReadResult r = source.Read();
    if (r.kind != ReadResult::Kind::kFrame) return r;
    frames->push_back(r.frame);
  }
}

TEST(VideoFileSource, PlaysEveryFrameInOrderAtItsTimeInTheVideo) {
  VideoFileSource source(Video("whole.avi"));
  ASSERT_EQ(source.Open(), "");
  EXPECT_DOUBLE_EQ(source.FrameRate(), kRate);
  EXPECT_FALSE(source.Live());
  std::vector<CapturedFrame> frames;
  const ReadResult end = ReadAll(source, &frames);
  ASSERT_EQ(frames.size(), static_cast<std::size_t>(kFrames));
  for (int k = 0; k < kFrames; ++k) {
    EXPECT_EQ(testing::FrameNumber(frames[k].image), k);
    EXPECT_EQ(frames[k].image.size(), kSize);
    EXPECT_EQ(frames[k].image.type(), CV_8UC3);
    EXPECT_EQ(frames[k].utime - frames[0].utime, 40'000 * k) << "frame " << k;
  }
  // Stamped in the epoch's clock: within a minute of now.
  EXPECT_NEAR(static_cast<double>(frames[0].utime), static_cast<double>(WallUtime()), 60e6);
  EXPECT_EQ(end.kind, ReadResult::Kind::kEnd);
  EXPECT_NE(end.reason.find("ended after 20 frames"), std::string::npos) << end.reason;
}

TEST(VideoFileSource, AVideoCutShortFailsAfterTheFramesItHas) {
  const std::string cut = ::testing::TempDir() + "/video_file_source_cut.avi";
  testing::WriteCutShort(Video("to_cut.avi"), cut, 0.5);
  VideoFileSource source(cut);
  ASSERT_EQ(source.Open(), "");
  std::vector<CapturedFrame> frames;
  const ReadResult end = ReadAll(source, &frames);
  ASSERT_GT(frames.size(), 0u);
  ASSERT_LT(frames.size(), static_cast<std::size_t>(kFrames));
  for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
    EXPECT_EQ(testing::FrameNumber(frames[k].image), static_cast<int>(k));
  }
  EXPECT_EQ(end.kind, ReadResult::Kind::kFailed);
  EXPECT_EQ(end.reason, "the video '" + cut + "' ends after " + std::to_string(frames.size()) +
                            " of the 20 frames its header announces: it is cut short");
}

TEST(VideoFileSource, AFileThatIsNoVideoIsRefusedInOneLine) {
  const std::string garbage = ::testing::TempDir() + "/video_file_source_garbage.avi";
  testing::WriteGarbage(garbage);
  VideoFileSource source(garbage);
  const std::string reason = source.Open();
  EXPECT_EQ(reason, "the video '" + garbage + "' is not a video that OpenCV reads (FFmpeg)");
  EXPECT_EQ(reason.find('\n'), std::string::npos);
}

TEST(VideoFileSource, ASecondPassGoesOnWithTheClock) {
  VideoFileSource source(Video("looped.avi"));
  ASSERT_EQ(source.Open(), "");
  std::vector<CapturedFrame> first, second;
  ASSERT_EQ(ReadAll(source, &first).kind, ReadResult::Kind::kEnd);
  ASSERT_TRUE(source.Restart());
  ASSERT_EQ(ReadAll(source, &second).kind, ReadResult::Kind::kEnd);
  ASSERT_EQ(second.size(), first.size());
  EXPECT_EQ(testing::FrameNumber(second[0].image), 0);
  EXPECT_EQ(second[0].utime, first.back().utime + 40'000);
  EXPECT_EQ(second.back().utime - second[0].utime, first.back().utime - first[0].utime);
}

}  // namespace
}  // namespace billiard::camera_node
