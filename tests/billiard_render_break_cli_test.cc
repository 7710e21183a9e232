// `billiard render-break` as a user runs it: the video read back with OpenCV (its frame count,
// size and rate as asked), the camera model it writes, the balls' places at the end on the
// playing surface and each seen in the last frame where the camera puts it (a ball's colour, not
// the cloth's); a bad request is a usage error.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>

#include "sim/camera/camera_model.h"
#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::OneObject;

constexpr int kWidth = 320, kHeight = 180;
constexpr double kFps = 10.0, kSeconds = 1.5;
// The pool-9ft playing surface [m] (sim/params/tables) and the ball's radius.
constexpr double kLength = 2.54, kWidthM = 1.27, kRadius = 0.028575;
// A ball's pixel differs from the cloth's by more than this (sum of the BGR differences): the
// cloth is one colour, every ball (the white, the colours, the black) far from it.
constexpr int kNotCloth = 60;

std::string Path(const std::string& name) {
  return (std::filesystem::path(::testing::TempDir()) / ("render_break_" + name)).string();
}

int Difference(const cv::Vec3b& a, const cv::Vec3b& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

TEST(RenderBreak, WritesTheVideoAskedForWithTheBallsWhereItsCameraSeesThem) {
  const std::string args = "render-break --out " + Path("break.avi") + " --camera-out " +
                           Path("camera.json") + " --width 320 --height 180 --fps 10 --duration 1.5";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << r.out;
  const nlohmann::json j = OneObject(r, args);
  const int frames = static_cast<int>(kFps * kSeconds);
  EXPECT_EQ(j["frames"], frames);

  cv::VideoCapture video(Path("break.avi"));
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_WIDTH), kWidth);
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_HEIGHT), kHeight);
  EXPECT_NEAR(video.get(cv::CAP_PROP_FPS), kFps, 1e-6);
  cv::Mat frame, last;
  int read = 0;
  while (video.read(frame)) {
    frame.copyTo(last);
    ++read;
  }
  EXPECT_EQ(read, frames);

  const billiard::camera::CameraModel camera =
      billiard::camera::LoadCameraModel(Path("camera.json"));
  EXPECT_EQ(camera.width, kWidth);
  EXPECT_EQ(camera.height, kHeight);
  // The cloth's colour: the middle of the table's left half, where no ball is after this break
  // (checked below: every ball's place is tested apart).
  const cv::Vec3b cloth = last.at<cv::Vec3b>(kHeight / 2, kWidth / 8 + kWidth / 16);
  ASSERT_FALSE(j["balls_at_end"].empty());
  for (const nlohmann::json& b : j["balls_at_end"]) {
    const double x = b["x"], y = b["y"];
    EXPECT_GT(x, 0.0);
    EXPECT_LT(x, kLength);
    EXPECT_GT(y, 0.0);
    EXPECT_LT(y, kWidthM);
    const Eigen::Vector2d px = camera.Project(Eigen::Vector3d(x, y, kRadius));
    const cv::Vec3b seen = last.at<cv::Vec3b>(static_cast<int>(std::lround(px.y())),
                                              static_cast<int>(std::lround(px.x())));
    EXPECT_GT(Difference(seen, cloth), kNotCloth) << "ball " << b["id"] << " at " << px.transpose();
  }
}

TEST(RenderBreak, ABadRequestIsAUsageError) {
  EXPECT_EQ(Billiard("render-break --out " + Path("x.avi") + " --duration 0.2 --at-rest 0.3").status,
            2);
  EXPECT_EQ(Billiard("render-break --out /nonexistent/dir/x.avi").status, 2);
  EXPECT_EQ(Billiard("render-break").status, 2);  // --out is required
}

}  // namespace
