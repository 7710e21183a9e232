// Table calibration: marker centres and camera pose on frames rendered from a known camera, and
// the markers of the real photograph.
#include "estimator/table_calibration.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <opencv2/aruco.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "estimator/ball_detector.h"
#include "estimator/testing/real_table_photo.h"
#include "tests/support/test_data.h"

namespace billiard::estimator {
namespace {

// A tilted camera over a 2.54 x 1.27 m table.
camera::CameraModel TiltedCamera() {
  const physics::TableParameters table{2.54, 1.27};
  camera::CameraModel c = camera::CameraModel::Overhead(table, 1280, 720, 2.4, 0.75);
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(-0.02, Eigen::Vector3d::UnitY()))
                                   .toRotationMatrix();
  const Eigen::Vector3d centre = c.Centre();
  c.rotation = tilt * c.rotation;
  c.translation = -c.rotation * centre;
  return c;
}

// Draws ArUco markers (side `side` [m], white border when inverted) flat at the layout's
// centres, as `camera` sees them, on a dark rail around a green cloth.
cv::Mat RenderMarkers(const camera::CameraModel& camera, const MarkerLayout& layout, double side,
                      bool inverted) {
  cv::Mat image(camera.height, camera.width, CV_8UC3, cv::Scalar(40, 50, 110));
  std::vector<cv::Point> cloth;
  for (const auto& corner : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2.54, 0, 0),
                             Eigen::Vector3d(2.54, 1.27, 0), Eigen::Vector3d(0, 1.27, 0)}) {
    const Eigen::Vector2d p = camera.Project(corner);
    cloth.emplace_back(static_cast<int>(p.x()), static_cast<int>(p.y()));
  }
  cv::fillConvexPoly(image, cloth, cv::Scalar(60, 140, 40), cv::LINE_AA);
  const auto dictionary = cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50);
  for (int i = 0; i < 4; ++i) {
    cv::Mat marker;
    cv::aruco::drawMarker(dictionary, i, 120, marker, 1);
    // A quiet zone of one cell around it, in the opposite colour of the border.
    cv::copyMakeBorder(marker, marker, 20, 20, 20, 20, cv::BORDER_CONSTANT, 255);
    if (inverted) marker = 255 - marker;
    const double half = side * 160.0 / 120.0 / 2;  // the quiet zone included
    std::vector<cv::Point2f> from = {{0, 0}, {160, 0}, {160, 160}, {0, 160}}, to;
    // Marker image up = table +y (up the image).
    for (const auto& [dx, dy] :
         {std::pair{-1, 1}, std::pair{1, 1}, std::pair{1, -1}, std::pair{-1, -1}}) {
      const Eigen::Vector2d p =
          camera.Project(layout.centres[i] + Eigen::Vector3d(dx * half, dy * half, 0));
      to.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    }
    cv::Mat warped, mask;
    cv::Mat colour;
    cv::cvtColor(marker, colour, cv::COLOR_GRAY2BGR);
    const cv::Mat h = cv::getPerspectiveTransform(from, to);
    cv::warpPerspective(colour, warped, h, image.size(), cv::INTER_LINEAR);
    cv::warpPerspective(cv::Mat(160, 160, CV_8U, cv::Scalar(255)), mask, h, image.size(),
                        cv::INTER_NEAREST);
    warped.copyTo(image, mask);
  }
  return image;
}

TEST(TableCalibration, RecoversAKnownCameraFromRenderedMarkers) {
  const camera::CameraModel truth = TiltedCamera();
  const MarkerLayout layout = MarkerLayout::AroundTable({2.54, 1.27}, 0.1, 0.04);
  for (const bool inverted : {false, true}) {
    double marker_error = 0;
    const cv::Mat image = RenderMarkers(truth, layout, 0.08, inverted);
    const auto result = CalibrateTable(image, layout, truth);
    ASSERT_TRUE(result.has_value()) << (inverted ? "inverted" : "normal");
    for (int i = 0; i < 4; ++i) {
      marker_error =
          std::max(marker_error, (result->points[i] - truth.Project(layout.centres[i])).norm());
      EXPECT_LT((result->points[i] - truth.Project(layout.centres[i])).norm(), 0.5)
          << "marker " << i << (inverted ? " (inverted)" : "");
    }
    EXPECT_LT(result->rms_reprojection_px, 0.5);
    // The table as the two cameras see it, at ball height: within 2 mm (0.8 px here). Four marker
    // centres found to about 0.2 px fix the pose no better; the 0.5 mm of the estimator needs
    // more points (a checkerboard) or the balls themselves.
    double worst = 0;
    for (double x = 0; x <= 2.54; x += 0.254) {
      for (double y = 0; y <= 1.27; y += 0.254) {
        const Eigen::Vector3d p(x, y, 0.026);
        const Eigen::Vector3d back = result->camera.Unproject(truth.Project(p), p.z());
        EXPECT_LT((back - p).norm(), 2e-3) << x << ", " << y;
        worst = std::max(worst, (back - p).norm());
      }
    }
    std::fprintf(stderr,
                 "%s markers: centres within %.2f px, table at ball height within %.2f mm\n",
                 inverted ? "inverted" : "normal", marker_error, 1e3 * worst);
  }
}

TEST(TableCalibration, FindsTheMarkersOfTheRealPhotograph) {
  BILLIARD_TEST_DATA_OR_SKIP(path, testing::kRealTablePhoto);
  const cv::Mat photo = cv::imread(path, cv::IMREAD_COLOR);
  ASSERT_FALSE(photo.empty()) << path;
  const auto markers = FindCornerMarkers(photo);
  ASSERT_TRUE(markers.has_value());
  // Read off the image by hand: the centres of the four white-bordered squares.
  const std::array<Eigen::Vector2d, 4> hand = {Eigen::Vector2d(144, 37), Eigen::Vector2d(1177, 34),
                                               Eigen::Vector2d(1172, 683),
                                               Eigen::Vector2d(149, 681)};
  for (int i = 0; i < 4; ++i) EXPECT_LT(((*markers)[i] - hand[i]).norm(), 3.0) << "marker " << i;

  // The photo's own geometry: about 1.75 mm per pixel (a 52.5 mm snooker ball is 15 px across
  // its radius), the cloth's bottom-left corner at pixel (80, 665). With the markers placed
  // accordingly, the pose reprojects them and the balls come out at their size.
  const auto table_point = [](double u, double v) {
    return Eigen::Vector3d((u - 80) * 0.00175, (665 - v) * 0.00175, 0.04);
  };
  MarkerLayout layout;
  for (int i = 0; i < 4; ++i) layout.centres[i] = table_point(hand[i].x(), hand[i].y());
  const auto result = CalibrateTable(photo, layout);
  ASSERT_TRUE(result.has_value());
  EXPECT_LT(result->rms_reprojection_px, 3.0);
  EXPECT_NEAR(ExpectedRadiusPx(result->camera, 0.02625), testing::kRealTablePhotoRadiusPx, 1.5);
}

}  // namespace
}  // namespace billiard::estimator
