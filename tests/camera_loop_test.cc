// run_loop.sh --camera as a user runs it: a break rendered by the table simulator's camera and
// written as a video, played by camera_node into estimator_node, and the tracks the run prints
// against the truth; a video cut short and a file that is no video said in camera_node's one
// line, with exit 1 and the summary of what was seen.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "sim/camera/camera_model.h"
#include "tests/support/run_command.h"
#include "tools/camera_node/testing/break_video.h"
#include "tools/camera_node/testing/video_files.h"

namespace {

using billiard::testing::RunCommandApart;
using billiard::testing::SeparateOutput;
namespace video = billiard::camera_node::testing;

// 640x360: 4.3 mm a pixel on the table, a short test; two seconds of the break.
constexpr int kWidth = 640, kHeight = 360;
constexpr double kSeconds = 2.0;
// Where each ball's track ends against where the ball is at the last frame [m]: under a pixel
// at this size (1.6 mm at worst on this break).
constexpr double kAtTheEnd = 3e-3;

class CameraLoop : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    video::BreakVideoOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.duration = kSeconds;
    break_ = new video::BreakVideo(video::WriteBreakVideo(Path("break.avi"), options));
    std::ofstream(Path("camera.json")) << billiard::camera::CameraModelJson(break_->camera);
  }
  static void TearDownTestSuite() { delete break_; }

  // As the script names it (its real path).
  static std::string Path(const std::string& name) {
    return (std::filesystem::path(::testing::TempDir()) / ("camera_loop_" + name))
        .lexically_normal()
        .string();
  }

  static bool NoMulticast(const SeparateOutput& r) {
    return r.err.find("--camera needs UDP multicast") != std::string::npos;
  }

  // The lines of `text` that contain `what`.
  static std::vector<std::string> LinesWith(const std::string& text, const std::string& what) {
    std::vector<std::string> found;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      if (line.find(what) != std::string::npos) found.push_back(line);
    }
    return found;
  }

  static video::BreakVideo* break_;
};

video::BreakVideo* CameraLoop::break_ = nullptr;

TEST_F(CameraLoop, ABreaksVideoIsTrackedToWhereEveryBallIs) {
  const SeparateOutput r =
      RunCommandApart(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json --camera " +
                      Path("break.avi") + " --camera-model " + Path("camera.json"));
  if (NoMulticast(r)) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const int frames = static_cast<int>(break_->truth.size());
  EXPECT_EQ(j["source"], "the video '" + Path("break.avi") + "' ended after " +
                             std::to_string(frames) + " frames");
  EXPECT_EQ(j["camera"]["published"], frames);
  EXPECT_EQ(j["camera"]["dropped"], 0);
  EXPECT_EQ(j["camera"]["counters"]["source_state"], 2);
  EXPECT_EQ(j["estimator"]["dropped"], 0);
  const nlohmann::json& tracks = j["tracks"];
  EXPECT_EQ(tracks["states"], frames);
  EXPECT_NEAR(tracks["seconds"].get<double>(), (frames - 1) / break_->fps, 1e-6);
  // Every ball on the table at the end has a track that ends where it is.
  const auto& at_end = break_->truth.back();
  EXPECT_EQ(tracks["balls_at_end"], static_cast<int>(at_end.size()));
  for (const auto& [id, truth] : at_end) {
    double nearest = INFINITY;
    for (const nlohmann::json& t : tracks["tracks"]) {
      if (std::abs(t["last_s"].get<double>() - tracks["seconds"].get<double>()) > 1e-6) continue;
      nearest = std::min(nearest, std::hypot(t["last"][0].get<double>() - truth.x(),
                                             t["last"][1].get<double>() - truth.y()));
    }
    EXPECT_LT(nearest, kAtTheEnd) << "ball " << id;
  }
  // The same on stderr, for a person: the source's line, the health, a row a track.
  EXPECT_EQ(LinesWith(r.err, "camera: the video").size(), 1u) << r.err;
  EXPECT_EQ(LinesWith(r.err, " frames published, 0 failed, the source ended").size(), 1u) << r.err;
  EXPECT_EQ(LinesWith(r.err, " tracks over ").size(), 1u) << r.err;
}

TEST_F(CameraLoop, AVideoCutShortIsOneLineAndExitsOne) {
  video::WriteCutShort(Path("break.avi"), Path("cut.avi"), 0.5);
  const SeparateOutput r =
      RunCommandApart(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json --camera " +
                      Path("cut.avi") + " --camera-model " + Path("camera.json"));
  if (NoMulticast(r)) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.status, 1) << r.err;
  const std::vector<std::string> said = LinesWith(r.err, "cut short");
  ASSERT_EQ(said.size(), 1u) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ("camera: " + j["source"].get<std::string>(), said[0]);
  EXPECT_EQ(j["camera"]["counters"]["source_state"], 3);
  EXPECT_GT(j["tracks"]["states"].get<int>(), 0);
  EXPECT_EQ(j["tracks"]["states"], j["camera"]["published"]);
}

TEST_F(CameraLoop, AFileThatIsNoVideoIsOneLineAndExitsOne) {
  video::WriteGarbage(Path("garbage.avi"));
  const SeparateOutput r =
      RunCommandApart(std::string("bash ") + RUN_LOOP_SCRIPT + " --no-build --json --camera " +
                      Path("garbage.avi") + " --camera-model " + Path("camera.json"));
  if (NoMulticast(r)) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.status, 1) << r.err;
  ASSERT_EQ(LinesWith(r.err, "is not a video").size(), 1u) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["source"],
            "the video '" + Path("garbage.avi") + "' is not a video that OpenCV reads (FFmpeg)");
  EXPECT_EQ(j["camera"]["published"], 0);
  EXPECT_EQ(j["camera"]["counters"]["source_state"], 3);
  EXPECT_EQ(j["tracks"]["states"], 0);
}

}  // namespace
