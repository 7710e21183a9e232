// The table region's geometry (table_finder.h's TableRegion): split from the finder, which fills
// it.
#include "estimator/table_finder.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/table_edges.h"
#include "estimator/table_partial.h"

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

// The corners in the pinhole's pixels (the frame's through no lens).
std::array<Eigen::Vector2d, 4> PinholeCorners(const RadialLens& lens,
                                              const std::array<Eigen::Vector2d, 4>& corners) {
  std::array<Eigen::Vector2d, 4> pinhole;
  for (int i = 0; i < 4; ++i) pinhole[i] = lens.ToPinhole(corners[i]);
  return pinhole;
}

// The homography `h` about table point `q`: the pinhole pixel it maps `q` to, and its Jacobian
// there (pinhole pixels per table width along the table's x and y).
struct LocalMap {
  Eigen::Vector2d pinhole;
  Eigen::Matrix2d jacobian;
};
LocalMap LocalMapAt(const Eigen::Matrix3d& h, const Eigen::Vector2d& q) {
  const Eigen::Vector3d p = h * q.homogeneous();
  LocalMap map{p.hnormalized(), Eigen::Matrix2d()};
  for (int j = 0; j < 2; ++j) {
    map.jacobian(0, j) = (h(0, j) - p.x() / p.z() * h(2, j)) / p.z();
    map.jacobian(1, j) = (h(1, j) - p.y() / p.z() * h(2, j)) / p.z();
  }
  return map;
}

}  // namespace

bool TableRegion::Contains(const Eigen::Vector2d& pixel, double margin_px) const {
  if (lens.IsPinhole()) return InsideQuadrilateral(corners, pixel, margin_px);
  return InsideQuadrilateral(PinholeCorners(lens, corners), lens.ToPinhole(pixel), margin_px);
}

bool TableRegion::InsideCloth(const Eigen::Vector2d& pixel, double margin_px) const {
  if (lens.IsPinhole()) return InsideQuadrilateral(cloth_corners, pixel, margin_px);
  return InsideQuadrilateral(PinholeCorners(lens, cloth_corners), lens.ToPinhole(pixel),
                             margin_px);
}

std::array<Eigen::Vector2d, 8> TableRegion::PocketPlaces() const {
  std::array<Eigen::Vector2d, 8> places;
  const double a = kTableAspect;
  const std::array<Eigen::Vector2d, 8> table = {
      {{0, 0}, {a / 2, 0}, {a, 0}, {a, 0.5}, {a, 1}, {a / 2, 1}, {0, 1}, {0, 0.5}}};
  for (int i = 0; i < 8; ++i) {
    places[i] = lens.ToImage((image_from_table * table[i].homogeneous()).hnormalized());
  }
  return places;
}

double TableRegion::InverseDepthAt(const Eigen::Vector2d& pixel) const {
  return inverse_depth.dot(lens.ToPinhole(pixel).homogeneous());
}

Eigen::Vector2d TableRegion::TableAt(const Eigen::Vector2d& pixel) const {
  return (image_from_table.inverse() * lens.ToPinhole(pixel).homogeneous()).hnormalized();
}

Eigen::Matrix2d TableRegion::JacobianAt(const Eigen::Vector2d& pixel) const {
  return LocalMapAt(image_from_table, TableAt(pixel)).jacobian;
}

double TableRegion::PixelsPerWidthAt(const Eigen::Vector2d& pixel) const {
  const LocalMap map = LocalMapAt(image_from_table, TableAt(pixel));
  return Eigen::JacobiSVD<Eigen::Matrix2d>(map.jacobian).singularValues()(0) *
         lens.MagnificationAt(map.pinhole);
}

double TableRegion::TableDistancePx(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  return (TableAt(a) - TableAt(b)).norm() * PixelsPerWidthAt(0.5 * (a + b));
}

double TableRegion::DistanceToSide(int side, const Eigen::Vector2d& pixel) const {
  const Eigen::Vector2d a = lens.ToPinhole(corners[side]);
  const Eigen::Vector2d b = lens.ToPinhole(corners[(side + 1) % 4]);
  const Eigen::Vector3d line = a.homogeneous().cross(b.homogeneous());
  if (lens.IsPinhole()) return std::abs(line.dot(pixel.homogeneous())) / line.head<2>().norm();
  const Eigen::Vector2d q = lens.ToPinhole(pixel), along = (b - a).normalized();
  const Eigen::Vector2d foot = a + along * along.dot(q - a);
  return (lens.ToImage(foot) - pixel).norm();
}

Eigen::Vector2d TableRegion::Centre() const {
  return lens.ToImage(
      (image_from_table * Eigen::Vector3d(0.5 * kTableAspect, 0.5, 1.0)).hnormalized());
}

cv::Rect TableRegion::Bounds() const {
  std::vector<cv::Point2f> points;
  for (int i = 0; i < 4; ++i) {
    points.emplace_back(static_cast<float>(cloth_corners[i].x()),
                        static_cast<float>(cloth_corners[i].y()));
    if (lens.IsPinhole()) continue;
    // Through a lens a side bows: its middle is the farthest it goes from the corners' chord.
    const Eigen::Vector2d middle = lens.ToImage(
        0.5 * (lens.ToPinhole(cloth_corners[i]) + lens.ToPinhole(cloth_corners[(i + 1) % 4])));
    points.emplace_back(static_cast<float>(middle.x()), static_cast<float>(middle.y()));
  }
  return cv::boundingRect(points);
}

bool CutByFrame(const TableRegion& table, const cv::Size& frame_size) {
  return table.side_out_of_frame >= 0 ||
         !SidesAlongBorder(table.cloth_corners, frame_size,
                           kFrameEdgePx * SearchReduction(frame_size))
              .empty();
}

}  // namespace billiard::estimator
