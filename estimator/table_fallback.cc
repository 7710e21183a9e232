#include "estimator/table_fallback.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/ball_scale.h"
#include "estimator/cloth_model.h"
#include "estimator/table_edges.h"

namespace billiard::estimator {

namespace {

Eigen::Vector2d ToFull(const Eigen::Vector2d& small, double scale) {
  return (small.array() + 0.5) / scale - 0.5;
}

Eigen::Vector2d ToSmall(const Eigen::Vector2d& full, double scale) {
  return (full.array() + 0.5) * scale - 0.5;
}

// The homography taking the table's plane (in table widths, x along the long side in [0, 2]) to
// the image through the four image points of its corners (0, 0), (2, 0), (2, 1), (0, 1).
Eigen::Matrix3d HomographyThrough(const std::array<Eigen::Vector2d, 4>& pixels) {
  const std::array<Eigen::Vector2d, 4> unit = {Eigen::Vector2d(0, 0),
                                               Eigen::Vector2d(kTableAspect, 0),
                                               Eigen::Vector2d(kTableAspect, 1),
                                               Eigen::Vector2d(0, 1)};
  std::vector<cv::Point2f> from, to;
  for (int i = 0; i < 4; ++i) {
    from.emplace_back(static_cast<float>(unit[i].x()), static_cast<float>(unit[i].y()));
    to.emplace_back(static_cast<float>(pixels[i].x()), static_cast<float>(pixels[i].y()));
  }
  const cv::Mat h = cv::getPerspectiveTransform(from, to);
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) m(i, j) = h.at<double>(i, j);
  }
  return m;
}

// The inverse depth of the table's plane from its homography, 1 at the table's centre (as
// FindTable sets it).
void SetInverseDepth(TableRegion* region) {
  const Eigen::Vector3d w = region->image_from_table.inverse().row(2).transpose();
  region->inverse_depth = w / w.dot(region->Centre().homogeneous());
}

// The playing surface's corners at the noses' height, through the camera.
std::array<Eigen::Vector2d, 4> Projected(const CalibratedTable& c) {
  const double l = c.table.length, w = c.table.width, z = c.nose_height;
  const std::array<Eigen::Vector3d, 4> corners = {
      Eigen::Vector3d(0, 0, z), Eigen::Vector3d(l, 0, z), Eigen::Vector3d(l, w, z),
      Eigen::Vector3d(0, w, z)};
  std::array<Eigen::Vector2d, 4> pixels;
  for (int i = 0; i < 4; ++i) pixels[i] = c.camera.Project(corners[i]);
  return pixels;
}

// The largest over the smallest distance of the playing surface's corners from the camera.
double DepthRatio(const CalibratedTable& c) {
  double nearest = HUGE_VAL, farthest = 0;
  for (const double x : {0.0, c.table.length}) {
    for (const double y : {0.0, c.table.width}) {
      const double depth =
          (c.camera.rotation * Eigen::Vector3d(x, y, c.nose_height) + c.camera.translation).z();
      nearest = std::min(nearest, depth);
      farthest = std::max(farthest, depth);
    }
  }
  return farthest / nearest;
}

// A mask at `scale` of the full resolution, of the given size, filled inside `corners`.
cv::Mat PolygonMask(const cv::Size& size, const std::array<Eigen::Vector2d, 4>& corners,
                    double scale) {
  std::vector<cv::Point> polygon;
  for (const auto& c : corners) {
    const Eigen::Vector2d p = ToSmall(c, scale);
    polygon.emplace_back(static_cast<int>(std::lround(p.x())),
                         static_cast<int>(std::lround(p.y())));
  }
  cv::Mat mask = cv::Mat::zeros(size, CV_8U);
  cv::fillConvexPoly(mask, polygon, 255);
  return mask;
}

// The cloth of a frame whose table the camera gives: FindTable's cloth (of a table found or not)
// within the cloth's outline, else the outline itself and the median colour inside it.
void ReadCloth(const cv::Mat& bgr, TableRegion* region) {
  const TableSearch search = FindTable(bgr);
  const std::optional<TableRegion>& found = search.table ? search.table : search.cloth;
  if (found) {
    region->mask_scale = found->mask_scale;
    region->cloth_colour = found->cloth_colour;
    const cv::Mat outline = PolygonMask(found->cloth.size(), region->cloth_corners,
                                        region->mask_scale);
    region->cloth = found->cloth & outline;
    region->surface = found->surface & outline;
    return;
  }
  const int factor = static_cast<int>(std::ceil(std::max(bgr.cols, bgr.rows) / kTableSearchSize));
  region->mask_scale = 1.0 / factor;
  const cv::Size small((bgr.cols + factor - 1) / factor, (bgr.rows + factor - 1) / factor);
  region->cloth = PolygonMask(small, region->corners, region->mask_scale);
  region->surface = region->cloth.clone();
  cv::Mat full_mask;
  cv::resize(region->cloth, full_mask, bgr.size(), 0, 0, cv::INTER_NEAREST);
  std::array<std::vector<uint8_t>, 3> channels;
  for (int y = 0; y < bgr.rows; y += factor) {
    for (int x = 0; x < bgr.cols; x += factor) {
      if (!full_mask.at<uint8_t>(y, x)) continue;
      for (int k = 0; k < 3; ++k) channels[k].push_back(bgr.at<cv::Vec3b>(y, x)[k]);
    }
  }
  for (int k = 0; k < 3 && !channels[k].empty(); ++k) {
    auto middle = channels[k].begin() + channels[k].size() / 2;
    std::nth_element(channels[k].begin(), middle, channels[k].end());
    region->cloth_colour[k] = *middle;
  }
}

}  // namespace

TableRegion TableSeenBy(const CalibratedTable& calibrated, const cv::Mat& bgr) {
  TableRegion region;
  region.origin = TableOrigin::kCalibrated;
  region.corners = Projected(calibrated);
  region.cloth_corners = region.corners;
  region.image_from_table = HomographyThrough(region.corners);
  SetInverseDepth(&region);
  region.depth_ratio = DepthRatio(calibrated);
  region.view =
      region.depth_ratio <= kOverheadDepthRatio ? TableView::kOverhead : TableView::kOblique;
  ReadCloth(bgr, &region);
  return region;
}

TableRegion ClothOnly(const TableRegion& cloth) {
  TableRegion region = cloth;
  region.origin = TableOrigin::kClothOnly;
  std::vector<cv::Point> points;
  cv::findNonZero(cloth.surface, points);
  const cv::RotatedRect box = cv::minAreaRect(points);
  cv::Point2f vertices[4];
  box.points(vertices);
  for (int i = 0; i < 4; ++i) {
    region.corners[i] = ToFull({vertices[i].x, vertices[i].y}, cloth.mask_scale);
  }
  region.cloth_corners = region.corners;
  // The long side first, then a similarity: the rectangle's centre at the table's, one scale
  // for both axes (its proportions need not be a table's: part of it may be out of frame).
  const bool first_long = (region.corners[1] - region.corners[0]).norm() >=
                          (region.corners[2] - region.corners[1]).norm();
  const Eigen::Vector2d a = region.corners[0], b = region.corners[1], c = region.corners[2];
  const Eigen::Vector2d along = first_long ? b - a : c - b, across = first_long ? c - b : b - a;
  const double pixels_per_width = std::sqrt(along.norm() * across.norm() / kTableAspect);
  Eigen::Matrix3d h = Eigen::Matrix3d::Identity();
  h.block<2, 1>(0, 0) = pixels_per_width * along.normalized();
  h.block<2, 1>(0, 1) = pixels_per_width * across.normalized();
  const Eigen::Vector2d centre = 0.5 * (a + c);
  h.block<2, 1>(0, 2) = centre - h.block<2, 2>(0, 0) * Eigen::Vector2d(0.5 * kTableAspect, 0.5);
  region.image_from_table = h;
  region.inverse_depth = Eigen::Vector3d::UnitZ();
  region.depth_ratio = 1.0;
  region.view = TableView::kOverhead;
  region.side_fit_rms_px = 0;
  return region;
}

std::optional<TableRegion> ClothWithBalls(const cv::Mat& bgr, const TableSearch& search) {
  std::vector<TableRegion> regions;
  if (search.cloth) regions.push_back(ClothOnly(*search.cloth));
  for (const TableRegion& other : search.other_cloths) regions.push_back(ClothOnly(other));
  if (regions.size() < 2) {  // nothing to choose between: no blobs to weigh
    return regions.empty() ? std::nullopt : std::optional<TableRegion>(regions.front());
  }
  std::vector<double> support;
  for (const TableRegion& region : regions) {
    const std::optional<BallScale> balls =
        ScaleFromBlobs(bgr, region, LearnClothModel(bgr, region));
    support.push_back(balls ? balls->support : 0.0);
  }
  // The first of the most supported: the likeliest colour where another has no more.
  return regions[std::max_element(support.begin(), support.end()) - support.begin()];
}

std::array<double, 4> ClothAtFrameEdges(const TableRegion& region) {
  const cv::Mat& surface = region.surface;
  const std::array<cv::Mat, 4> edges = {surface.col(0), surface.row(0),
                                        surface.col(surface.cols - 1),
                                        surface.row(surface.rows - 1)};
  // A pixel's place along its edge: an edge is one row or one column, the other coordinate 0.
  const auto along = [](const cv::Point& p) { return p.x + p.y; };
  std::array<double, 4> shares;
  for (int i = 0; i < 4; ++i) {
    // A convex surface meets an edge in one stretch, from its first pixel there to its last (a
    // ball the edge cuts is open to the frame: no hole the region's filling closed).
    std::vector<cv::Point> on;
    cv::findNonZero(edges[i], on);
    const auto [first, last] = std::minmax_element(
        on.begin(), on.end(), [&](const auto& a, const auto& b) { return along(a) < along(b); });
    const int stretch = on.empty() ? 0 : along(*last) - along(*first) + 1;
    shares[i] = static_cast<double>(stretch) / edges[i].total();
  }
  return shares;
}

}  // namespace billiard::estimator
