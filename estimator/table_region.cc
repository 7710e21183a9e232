// The table region's geometry (table_finder.h's TableRegion): split from the finder, which fills
// it.
#include "estimator/table_finder.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/table_edges.h"

namespace billiard::estimator {

const char* TableViewName(TableView view) {
  return view == TableView::kOverhead ? "overhead" : "oblique";
}

const char* TableOriginName(TableOrigin origin) {
  switch (origin) {
    case TableOrigin::kFound:
      return "found";
    case TableOrigin::kCalibrated:
      return "calibration";
    case TableOrigin::kClothOnly:
      return "cloth only";
  }
  return "found";
}

namespace {

bool InsideQuadrilateral(const std::array<Eigen::Vector2d, 4>& corners,
                         const Eigen::Vector2d& pixel, double margin_px) {
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = corners[i], b = corners[(i + 1) % 4];
    const Eigen::Vector2d edge = (b - a).normalized();
    const Eigen::Vector2d inward(-edge.y(), edge.x());
    const double sign = inward.dot(corners[(i + 2) % 4] - a) > 0 ? 1.0 : -1.0;
    if (sign * inward.dot(pixel - a) < margin_px) return false;
  }
  return true;
}

}  // namespace

bool TableRegion::Contains(const Eigen::Vector2d& pixel, double margin_px) const {
  return InsideQuadrilateral(corners, pixel, margin_px);
}

bool TableRegion::InsideCloth(const Eigen::Vector2d& pixel, double margin_px) const {
  return InsideQuadrilateral(cloth_corners, pixel, margin_px);
}

std::array<Eigen::Vector2d, 8> TableRegion::PocketPlaces() const {
  std::array<Eigen::Vector2d, 8> places;
  const double a = kTableAspect;
  const std::array<Eigen::Vector2d, 8> table = {
      {{0, 0}, {a / 2, 0}, {a, 0}, {a, 0.5}, {a, 1}, {a / 2, 1}, {0, 1}, {0, 0.5}}};
  for (int i = 0; i < 8; ++i) {
    places[i] = (image_from_table * table[i].homogeneous()).hnormalized();
  }
  return places;
}

double TableRegion::InverseDepthAt(const Eigen::Vector2d& pixel) const {
  return inverse_depth.dot(pixel.homogeneous());
}

Eigen::Vector2d TableRegion::TableAt(const Eigen::Vector2d& pixel) const {
  return (image_from_table.inverse() * pixel.homogeneous()).hnormalized();
}

double TableRegion::PixelsPerWidthAt(const Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d q = TableAt(pixel).homogeneous();
  const Eigen::Matrix3d& h = image_from_table;
  const Eigen::Vector3d p = h * q;
  Eigen::Matrix2d jacobian;
  for (int j = 0; j < 2; ++j) {
    jacobian(0, j) = (h(0, j) - p.x() / p.z() * h(2, j)) / p.z();
    jacobian(1, j) = (h(1, j) - p.y() / p.z() * h(2, j)) / p.z();
  }
  return Eigen::JacobiSVD<Eigen::Matrix2d>(jacobian).singularValues()(0);
}

double TableRegion::TableDistancePx(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  return (TableAt(a) - TableAt(b)).norm() * PixelsPerWidthAt(0.5 * (a + b));
}

Eigen::Vector2d TableRegion::Centre() const {
  return (image_from_table * Eigen::Vector3d(0.5 * kTableAspect, 0.5, 1.0)).hnormalized();
}

cv::Rect TableRegion::Bounds() const {
  std::vector<cv::Point2f> points;
  for (const auto& c : cloth_corners) {
    points.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
  }
  return cv::boundingRect(points);
}

}  // namespace billiard::estimator
