// The camera model against OpenCV's projection, and its inverse.
#include "sim/camera/camera_model.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "sim/physics/parameters.h"

namespace billiard::camera {
namespace {

const physics::TableParameters kTable{2.54, 1.27};
const std::array<double, 5> kLens{-0.12, 0.03, 4e-4, -3e-4, 0.0};

CameraModel Tilted() {
  CameraModel c = CameraModel::Overhead(kTable, 1280, 720, 2.5, 0.92, kLens);
  // A camera a little off the vertical, as mounted in practice.
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd(0.03, Eigen::Vector3d::UnitX()).toRotationMatrix() *
      Eigen::AngleAxisd(-0.02, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d centre = c.Centre();
  c.rotation = tilt * c.rotation;
  c.translation = -c.rotation * centre;
  return c;
}

TEST(CameraModel, ProjectsLikeOpenCV) {
  const CameraModel c = Tilted();
  cv::Mat k = (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
  cv::Mat r, rvec, tvec;
  cv::eigen2cv(c.rotation, r);
  cv::Rodrigues(r, rvec);
  cv::eigen2cv(c.translation, tvec);
  std::vector<cv::Point3d> points;
  for (double x = 0.0; x <= 2.54; x += 0.254) {
    for (double y = 0.0; y <= 1.27; y += 0.127) points.emplace_back(x, y, 0.0286);
  }
  std::vector<cv::Point2d> expected;
  cv::projectPoints(points, rvec, tvec, k, std::vector<double>(kLens.begin(), kLens.end()),
                    expected);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d p = c.Project({points[i].x, points[i].y, points[i].z});
    EXPECT_NEAR(p.x(), expected[i].x, 1e-9);
    EXPECT_NEAR(p.y(), expected[i].y, 1e-9);
  }
}

TEST(CameraModel, UnprojectInvertsProjectAtTheGivenHeight) {
  const CameraModel c = Tilted();
  for (double x = 0.0; x <= 2.54; x += 0.127) {
    for (double y = 0.0; y <= 1.27; y += 0.127) {
      const Eigen::Vector3d p(x, y, 0.0286);
      EXPECT_LT((c.Unproject(c.Project(p), p.z()) - p).norm(), 1e-9) << x << ", " << y;
    }
  }
}

TEST(CameraModel, OverheadCameraSeesTheWholeTableUprightAndFilled) {
  const CameraModel c = CameraModel::Overhead(kTable, 1280, 720);
  const Eigen::Vector2d origin = c.Project({0, 0, 0}), far = c.Project({2.54, 1.27, 0});
  EXPECT_GT(origin.x(), 0);
  EXPECT_LT(far.x(), 1279);
  EXPECT_GT(origin.y(), far.y());  // table y runs up the image
  EXPECT_NEAR(far.x() - origin.x(), 0.92 * 1280, 1e-6);
  // 2.54 m over 1178 px.
  EXPECT_NEAR(c.MetresPerPixel({1.27, 0.635, 0.0}), 2.54 / (0.92 * 1280), 1e-6);
}

TEST(CameraModel, ACameraLookingAtAPointSeesItInTheMiddleUprightAndLevel) {
  const Eigen::Vector3d eye(1.27, -1.5, 1.2), target(1.27, 0.635, 0.0);
  const CameraModel c = CameraModel::LookingAt(eye, target, 1280, 720, 1.0);
  EXPECT_LT((c.Project(target) - Eigen::Vector2d(c.cx, c.cy)).norm(), 1e-9);
  EXPECT_LT((c.Centre() - eye).norm(), 1e-12);
  EXPECT_NEAR(c.fx, 640.0 / std::tan(0.5), 1e-9);
  // Up the table's z is up the image; along the table's x (level, across the view) is right.
  EXPECT_LT(c.Project(target + Eigen::Vector3d(0, 0, 0.1)).y(), c.cy);
  EXPECT_GT(c.Project(target + Eigen::Vector3d(0.1, 0, 0)).x(), c.cx);
  EXPECT_NEAR(c.Project(target + Eigen::Vector3d(0.1, 0, 0)).y(), c.cy, 1e-9);
  // A rotation: orthonormal, right-handed.
  EXPECT_LT((c.rotation * c.rotation.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  EXPECT_NEAR(c.rotation.determinant(), 1.0, 1e-12);
  // The far side of the table is higher up the image and smaller than the near side.
  const double near = (c.Project({2.54, 0, 0}) - c.Project({0, 0, 0})).norm();
  const double far = (c.Project({2.54, 1.27, 0}) - c.Project({0, 1.27, 0})).norm();
  EXPECT_LT(far, near);
  EXPECT_LT(c.Project({1.27, 1.27, 0}).y(), c.Project({1.27, 0, 0}).y());
}

TEST(CameraModel, JsonRoundTripsAndBadFilesAreRefused) {
  const CameraModel c = Tilted();
  const CameraModel d = ParseCameraModel(CameraModelJson(c), "test");
  const Eigen::Vector3d p(0.7, 0.3, 0.02);
  EXPECT_LT((c.Project(p) - d.Project(p)).norm(), 1e-9);
  EXPECT_THROW(ParseCameraModel("{", "bad"), std::invalid_argument);
  EXPECT_THROW(ParseCameraModel(R"({"width":1280})", "bad"), std::invalid_argument);
  std::string not_rotation = CameraModelJson(c);
  const auto at = not_rotation.find("\"rotation\"");
  not_rotation.replace(not_rotation.find('[', at) + 1, 1, "7");  // first entry no longer unit
  EXPECT_THROW(ParseCameraModel(not_rotation, "bad"), std::invalid_argument);
}

}  // namespace
}  // namespace billiard::camera
