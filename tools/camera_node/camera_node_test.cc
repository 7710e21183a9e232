// The camera node in-process over memq://: a file's frames out as the table simulator sends its
// own, at the file's pace or as fast as they are read; a source that fails or stalls said in
// one line and in NODE_STATUS, the node going on reporting, never held by the source.
#include "tools/camera_node/camera_node.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "lcmtypes/billiard/image_t.hpp"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_loop.h"
#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node {
namespace {

namespace fs = std::filesystem;

const cv::Size kSize(160, 90);

std::string Video(const std::string& name, int frames, double rate) {
  const std::string path = ::testing::TempDir() + "/camera_node_" + name;
  testing::WriteMjpgVideo(path, testing::NumberedFrames(frames, kSize), rate);
  return path;
}

std::int64_t Counter(const node_status_t& s, const std::string& name) {
  for (int i = 0; i < s.num_counters; ++i) {
    if (s.counter_names[i] == name) return s.counter_values[i];
  }
  return -1;
}

// A camera node on an LCM of its own, with what it published and logged.
class CameraNodeTest : public ::testing::Test {
 protected:
  CameraNodeTest() {
    lcm_.subscribe(messages::kCameraImageChannel, &CameraNodeTest::OnImage, this);
    lcm_.subscribe(messages::kNodeStatusChannel, &CameraNodeTest::OnStatus, this);
  }

  void Start(std::unique_ptr<FrameSource> source, CameraNodeOptions options = {}) {
    node_ = std::make_unique<CameraNode>(lcm_, std::move(source), options,
                                         [this](const std::string& l) { log_.push_back(l); });
  }
  void Start(const SourceSpec& spec, CameraNodeOptions options = {}) {
    Start(MakeFrameSource(spec), options);
  }
  void RunToTheEnd() {
    nodes::HandleUntilIdle(lcm_, [this] { return node_->Work(); });
  }

  void OnImage(const lcm::ReceiveBuffer*, const std::string&, const image_t* m) {
    images_.push_back(*m);
    arrivals_.push_back(Clock::now());
  }
  void OnStatus(const lcm::ReceiveBuffer*, const std::string&, const node_status_t* m) {
    statuses_.push_back(*m);
  }

  static CameraNodeOptions Unpaced() {
    CameraNodeOptions options;
    options.paced = false;
    return options;
  }

  lcm::LCM lcm_{"memq://"};
  std::unique_ptr<CameraNode> node_;
  std::vector<std::string> log_;
  std::vector<image_t> images_;
  std::vector<Clock::time_point> arrivals_;
  std::vector<node_status_t> statuses_;
};

TEST_F(CameraNodeTest, AVideosFramesGoOutAsTheSimulatorSendsItsOwn) {
  const std::string path = Video("whole.avi", 12, 25.0);
  Start({SourceSpec::Kind::kVideo, path}, Unpaced());
  RunToTheEnd();
  ASSERT_EQ(images_.size(), 12u);
  for (std::size_t k = 0; k < images_.size(); ++k) {
    EXPECT_EQ(images_[k].pixelformat, image_t::PIXEL_FORMAT_MJPEG);
    const messages::DecodedImage decoded = messages::DecodeImage(images_[k]);
    ASSERT_TRUE(decoded.ok) << decoded.error;
    EXPECT_EQ(decoded.image.size(), kSize);
    EXPECT_EQ(testing::FrameNumber(decoded.image), static_cast<int>(k));
    EXPECT_EQ(images_[k].utime - images_[0].utime, 40'000 * static_cast<std::int64_t>(k));
  }
  EXPECT_EQ(node_->state(), SourceState::kEnded);
  EXPECT_EQ(log_, (std::vector<std::string>{
                      "the video '" + path + "' is open, played as fast as it is read",
                      "the video '" + path + "' ended after 12 frames"}));
  ASSERT_FALSE(statuses_.empty());
  const node_status_t& last = statuses_.back();
  EXPECT_EQ(last.node, "camera_node");
  EXPECT_EQ(last.published, 12);
  EXPECT_EQ(last.dropped, 0);
  EXPECT_EQ(Counter(last, "source_state"), static_cast<int>(SourceState::kEnded));
}

TEST_F(CameraNodeTest, TheJpegQualityIsTheCommandLines) {
  const std::string path = Video("quality.avi", 3, 25.0);
  CameraNodeOptions rough = Unpaced();
  rough.jpeg_quality = 20;
  Start({SourceSpec::Kind::kVideo, path}, rough);
  RunToTheEnd();
  ASSERT_EQ(images_.size(), 3u);
  const int rough_bytes = images_[0].size;
  images_.clear();
  CameraNodeOptions fine = Unpaced();
  fine.jpeg_quality = 98;
  Start({SourceSpec::Kind::kVideo, path}, fine);
  RunToTheEnd();
  ASSERT_EQ(images_.size(), 3u);
  EXPECT_GT(images_[0].size, rough_bytes);
}

TEST_F(CameraNodeTest, AFileIsPlayedAtItsOwnRateOrTheOneAsked) {
  const std::string path = Video("paced.avi", 10, 50.0);
  for (const double fps : {0.0, 25.0}) {
    images_.clear();
    arrivals_.clear();
    CameraNodeOptions options;
    options.fps = fps;
    Start({SourceSpec::Kind::kVideo, path}, options);
    RunToTheEnd();
    ASSERT_EQ(images_.size(), 10u);
    const double expected = 9 / (fps > 0 ? fps : 50.0);
    const double took = std::chrono::duration<double>(arrivals_.back() - arrivals_[0]).count();
    EXPECT_GT(took, expected - 0.01) << "fps " << fps;
    EXPECT_LT(took, expected + 0.15) << "fps " << fps;
    // The capture times are the video's whatever the pace.
    EXPECT_EQ(images_.back().utime - images_[0].utime, 9 * 20'000) << "fps " << fps;
  }
}

TEST_F(CameraNodeTest, AVideoCutShortIsOneLineAndTheNodeStaysUp) {
  const std::string cut = ::testing::TempDir() + "/camera_node_cut.avi";
  testing::WriteCutShort(Video("to_cut.avi", 20, 25.0), cut, 0.5);
  Start({SourceSpec::Kind::kVideo, cut}, Unpaced());
  RunToTheEnd();
  EXPECT_EQ(node_->state(), SourceState::kFailed);
  EXPECT_GT(images_.size(), 0u);
  EXPECT_LT(images_.size(), 20u);
  ASSERT_EQ(log_.size(), 2u);
  EXPECT_EQ(log_[1], "the video '" + cut + "' ends after " + std::to_string(images_.size()) +
                         " of the 20 frames its header announces: it is cut short");
  EXPECT_EQ(node_->end_reason(), log_[1]);
  ASSERT_FALSE(statuses_.empty());
  EXPECT_EQ(Counter(statuses_.back(), "source_state"), static_cast<int>(SourceState::kFailed));
  // It goes on reporting, once a second, and says nothing more.
  const std::size_t reported = statuses_.size();
  const Clock::time_point until = Clock::now() + std::chrono::milliseconds(1200);
  while (Clock::now() < until) {
    EXPECT_FALSE(node_->Work());
    nodes::HandleUntilIdle(lcm_);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  EXPECT_GT(statuses_.size(), reported);
  EXPECT_EQ(Counter(statuses_.back(), "source_state"), static_cast<int>(SourceState::kFailed));
  EXPECT_EQ(log_.size(), 2u);
}

TEST_F(CameraNodeTest, AFileThatIsNoVideoIsOneLineAndNoFrame) {
  const std::string garbage = ::testing::TempDir() + "/camera_node_garbage.avi";
  testing::WriteGarbage(garbage);
  Start({SourceSpec::Kind::kVideo, garbage}, Unpaced());
  RunToTheEnd();
  EXPECT_TRUE(images_.empty());
  ASSERT_EQ(log_.size(), 1u);
  EXPECT_EQ(log_[0], "the video '" + garbage + "' is not a video that OpenCV reads (FFmpeg)");
  ASSERT_FALSE(statuses_.empty());
  EXPECT_EQ(Counter(statuses_.back(), "source_state"), static_cast<int>(SourceState::kFailed));
}

TEST_F(CameraNodeTest, AnImageThatDoesNotDecodeIsAFailedFrameAndTheRestPlay) {
  const std::string dir = ::testing::TempDir() + "/camera_node_images";
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (int k = 0; k < 4; ++k) {
    if (k == 2) {
      testing::WriteGarbage(dir + "/2.png");
    } else {
      ASSERT_TRUE(
          cv::imwrite(dir + "/" + std::to_string(k) + ".png", testing::NumberedFrame(k, kSize)));
    }
  }
  Start({SourceSpec::Kind::kImages, dir}, Unpaced());
  RunToTheEnd();
  ASSERT_EQ(images_.size(), 3u);
  std::vector<int> numbers;
  for (const image_t& m : images_) {
    numbers.push_back(testing::FrameNumber(messages::DecodeImage(m).image));
  }
  EXPECT_EQ(numbers, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(node_->state(), SourceState::kEnded);
  EXPECT_EQ(node_->health().dropped(), 1);
  EXPECT_EQ(node_->health().last_error(), "'" + dir + "/2.png' is not an image that decodes");
  EXPECT_EQ(statuses_.back().dropped, 1);
  EXPECT_EQ(statuses_.back().published, 3);
}

// A camera that hands over one frame and then never returns from its read.
class StuckCamera : public FrameSource {
 public:
  std::string Describe() const override { return "the stuck camera"; }
  std::string Open() override { return ""; }
  ReadResult Read() override {
    if (reads_++ == 0) {
      ReadResult r;
      r.kind = ReadResult::Kind::kFrame;
      r.frame.image = testing::NumberedFrame(0, kSize);
      r.frame.utime = WallUtime();
      return r;
    }
    std::unique_lock<std::mutex> lock(gate->mutex);
    gate->released.wait(lock, [this] { return gate->open; });
    return {};
  }
  double FrameRate() const override { return 0.0; }
  bool Live() const override { return true; }

  struct Gate {
    std::mutex mutex;
    std::condition_variable released;
    bool open = false;
  };
  std::shared_ptr<Gate> gate = std::make_shared<Gate>();

 private:
  int reads_ = 0;
};

TEST_F(CameraNodeTest, AStalledCameraIsReportedAndNeverHoldsTheNode) {
  auto camera = std::make_unique<StuckCamera>();
  const std::shared_ptr<StuckCamera::Gate> gate = camera->gate;
  CameraNodeOptions options;
  options.reader.stall_timeout = std::chrono::milliseconds(300);
  Start(std::move(camera), options);
  const Clock::time_point start = Clock::now();
  Clock::duration longest_work{};
  while (node_->state() != SourceState::kFailed && Clock::now() - start < std::chrono::seconds(2)) {
    const Clock::time_point before = Clock::now();
    node_->Work();
    longest_work = std::max(longest_work, Clock::now() - before);
    nodes::HandleUntilIdle(lcm_);
  }
  EXPECT_EQ(node_->state(), SourceState::kFailed);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 0.6);
  EXPECT_LT(longest_work, kMaxWait + std::chrono::milliseconds(30));
  EXPECT_EQ(images_.size(), 1u);
  ASSERT_EQ(log_.size(), 2u);
  EXPECT_EQ(log_[0], "the stuck camera is open");
  EXPECT_EQ(log_[1], "the stuck camera gave no frame for 0.3 s: it stalled");
  EXPECT_EQ(Counter(statuses_.back(), "source_state"), static_cast<int>(SourceState::kFailed));
  node_.reset();  // without waiting for the stuck read
  std::lock_guard<std::mutex> lock(gate->mutex);
  gate->open = true;
  gate->released.notify_all();
}

}  // namespace
}  // namespace billiard::camera_node
