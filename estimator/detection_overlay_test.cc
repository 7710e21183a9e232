// The overlay draws each detection where it was found and leaves the rest of the frame alone.
#include "estimator/detection_overlay.h"

#include <gtest/gtest.h>

namespace billiard::estimator {
namespace {

TEST(DetectionOverlay, DrawsEachBallOnItsOutlineAndNothingElse) {
  const cv::Mat frame(200, 300, CV_8UC3, cv::Scalar(20, 90, 30));
  const std::vector<BallDetection> balls = {{Eigen::Vector2d(80, 100), 20.0, 0.9},
                                            {Eigen::Vector2d(220, 60), 15.0, 0.2}};
  const cv::Mat overlay = DetectionOverlay(frame, balls);
  ASSERT_EQ(overlay.size(), frame.size());
  ASSERT_EQ(overlay.type(), CV_8UC3);
  // On the confident ball's outline: green; on the doubtful one's: red.
  const cv::Vec3b confident = overlay.at<cv::Vec3b>(100, 60);  // 20 px left of (80, 100)
  EXPECT_GT(confident[1], 150);
  EXPECT_LT(confident[2], 100);
  const cv::Vec3b doubtful = overlay.at<cv::Vec3b>(75, 220);  // 15 px below (220, 60)
  EXPECT_GT(doubtful[2], 150);
  EXPECT_LT(doubtful[1], 100);
  // Far from both: the frame as it was, and the frame itself untouched.
  EXPECT_EQ(overlay.at<cv::Vec3b>(180, 150), frame.at<cv::Vec3b>(180, 150));
  EXPECT_EQ(
      cv::countNonZero((frame.reshape(1) != 20) & (frame.reshape(1) != 90) & (frame.reshape(1) != 30)),
      0);
}

TEST(DetectionOverlay, AGrayFrameIsDrawnInColour) {
  const cv::Mat gray(100, 100, CV_8UC1, cv::Scalar(128));
  const cv::Mat overlay = DetectionOverlay(gray, {{Eigen::Vector2d(50, 50), 10.0, 0.8}});
  ASSERT_EQ(overlay.type(), CV_8UC3);
  EXPECT_EQ(overlay.at<cv::Vec3b>(5, 5), cv::Vec3b(128, 128, 128));
}

// Found through a barrel lens, a side is drawn where the lens puts its straight line: on the
// bowed curve, not on the chord between its corners (some 12 px apart at the top side's middle).
TEST(DetectionOverlay, ATableFoundThroughALensIsDrawnWithCurvedSides) {
  cv::Mat image(200, 300, CV_8UC3, cv::Scalar(0, 0, 0));
  TableRegion table;
  table.lens.k1 = -0.3;
  table.lens.focal_px = 200;
  table.lens.centre = {149.5, 99.5};
  table.lens.canvas = {300, 200};
  const std::array<Eigen::Vector2d, 4> pinhole = {
      Eigen::Vector2d(10, 20), Eigen::Vector2d(290, 20), Eigen::Vector2d(290, 180),
      Eigen::Vector2d(10, 180)};
  for (int i = 0; i < 4; ++i) table.corners[i] = table.cloth_corners[i] = table.lens.ToImage(pinhole[i]);
  DrawTable(table, &image);
  const Eigen::Vector2d on_curve = table.lens.ToImage({150, 20});
  const Eigen::Vector2d chord = 0.5 * (table.corners[0] + table.corners[1]);
  ASSERT_GT((on_curve - chord).norm(), 8.0);
  const auto drawn = [&](const Eigen::Vector2d& p) {
    const cv::Vec3b c = image.at<cv::Vec3b>(static_cast<int>(std::lround(p.y())),
                                            static_cast<int>(std::lround(p.x())));
    return c[0] + c[1] + c[2] > 150;
  };
  EXPECT_TRUE(drawn(on_curve));
  EXPECT_FALSE(drawn(chord));
}

}  // namespace
}  // namespace billiard::estimator
