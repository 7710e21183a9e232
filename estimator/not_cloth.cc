#include "estimator/not_cloth.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/local_cloth.h"

namespace billiard::estimator {

using internal::Contrast;
using internal::Decompose;
using internal::LocalCloth;
using internal::MakeLocalCloth;

int NotClothMap::BlobFactor(const TableRegion& table) {
  const cv::Rect bounds = table.Bounds();
  return std::max(1, static_cast<int>(std::max(bounds.width, bounds.height) / kNotClothTableSize));
}

int NotClothMap::IntruderFactor(const BallScale& scale) {
  return std::max(1, static_cast<int>(scale.radius_at_centre / kIntruderRadiusPx));
}

NotClothMap::NotClothMap(const cv::Mat& bgr, const TableRegion& table, const ClothModel& cloth,
                         int factor)
    : region_(table.Bounds() & cv::Rect(0, 0, bgr.cols, bgr.rows)), factor_(std::max(1, factor)) {
  if (region_.empty()) return;
  cv::Mat small;
  cv::resize(bgr(region_), small, {}, 1.0 / factor_, 1.0 / factor_, cv::INTER_AREA);
  surface_ = cv::Mat::zeros(small.size(), CV_8U);
  std::vector<cv::Point> corners;
  for (const auto& c : table.corners) {
    const Eigen::Vector2d p = ToMap(c);
    corners.emplace_back(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
  }
  cv::fillConvexPoly(surface_, corners, 255);
  // The cloth's colour at each map pixel: its map resampled (cell coordinates of a pixel are an
  // affine function of the pixel's).
  const double per_cell = factor_ / cloth.cell;
  const cv::Matx23d cell_from_small(
      per_cell, 0, (region_.x + 0.5 * factor_ - 0.5) / cloth.cell - 0.5, 0, per_cell,
      (region_.y + 0.5 * factor_ - 0.5) / cloth.cell - 0.5);
  cv::Mat colour;
  cv::warpAffine(cloth.colour, colour, cell_from_small, small.size(),
                 cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
  mask_ = cv::Mat::zeros(small.size(), CV_8U);
  faint_ = cv::Mat::zeros(small.size(), CV_8U);
  for (int y = 0; y < small.rows; ++y) {
    const auto* in = small.ptr<cv::Vec3b>(y);
    const auto* on = surface_.ptr<uint8_t>(y);
    const auto* local_colour = colour.ptr<cv::Vec3f>(y);
    auto* out = mask_.ptr<uint8_t>(y);
    auto* faint = faint_.ptr<uint8_t>(y);
    for (int x = 0; x < small.cols; ++x) {
      if (!on[x]) continue;
      const LocalCloth local = MakeLocalCloth(local_colour[x], cloth.noise);
      float along, across;
      Decompose(cv::Vec3f(in[x][0], in[x][1], in[x][2]), local, &along, &across);
      const float contrast = Contrast(along, across, local);
      out[x] = contrast >= 1.0f ? 255 : 0;
      faint[x] = contrast >= kIntruderFaintContrast ? 255 : 0;
    }
  }
}

Eigen::Vector2d NotClothMap::ToFull(const Eigen::Vector2d& map_pixel) const {
  return (map_pixel.array() + 0.5) * factor_ - 0.5 +
         Eigen::Array2d(region_.x, region_.y);
}

Eigen::Vector2d NotClothMap::ToMap(const Eigen::Vector2d& full_pixel) const {
  return (full_pixel.array() - Eigen::Array2d(region_.x, region_.y) + 0.5) / factor_ - 0.5;
}

cv::Mat NotClothMap::Intruders(const BallScale& scale) const {
  cv::Mat intruders = cv::Mat::zeros(mask_.size(), CV_8U);
  if (mask_.empty()) return intruders;
  const double radius = scale.radius_at_centre / factor_;
  const int opening = std::max(1, static_cast<int>(std::lround(kIntruderOpeningRadii * radius)));
  const cv::Mat disc =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * opening + 1, 2 * opening + 1});
  cv::Mat opened, faint;
  cv::morphologyEx(mask_, opened, cv::MORPH_OPEN, disc);
  cv::morphologyEx(faint_, faint, cv::MORPH_OPEN, disc);
  // The surface's edge: its pixels with a neighbour off it (or off the frame).
  cv::Mat inner, edge;
  cv::erode(surface_, inner, cv::Mat(), {-1, -1}, 1, cv::BORDER_CONSTANT, 0);
  cv::subtract(surface_, inner, edge);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(opened, labels, stats, centroids, 8);
  std::vector<bool> on_edge(n, false);
  for (int y = 0; y < labels.rows; ++y) {
    const auto* label = labels.ptr<int>(y);
    const auto* at_edge = edge.ptr<uint8_t>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (at_edge[x] && label[x] > 0) on_edge[label[x]] = true;
    }
  }
  std::vector<bool> intruder(n, false);
  for (int i = 1; i < n; ++i) {
    const double local_radius =
        scale.RadiusAt(ToFull({centroids.at<double>(i, 0), centroids.at<double>(i, 1)})) /
        factor_;
    intruder[i] = on_edge[i] && stats.at<int>(i, cv::CC_STAT_AREA) >=
                                    kIntruderBallAreas * M_PI * local_radius * local_radius;
  }
  // The faint not-cloth joined to an intruder.
  cv::Mat faint_labels;
  const int m = cv::connectedComponents(faint, faint_labels, 8);
  std::vector<bool> joined(m, false);
  for (int y = 0; y < labels.rows; ++y) {
    const auto* label = labels.ptr<int>(y);
    const auto* faint_label = faint_labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x) {
      if (intruder[label[x]] && faint_label[x] > 0) joined[faint_label[x]] = true;
    }
  }
  for (int y = 0; y < labels.rows; ++y) {
    const auto* faint_label = faint_labels.ptr<int>(y);
    auto* out = intruders.ptr<uint8_t>(y);
    for (int x = 0; x < labels.cols; ++x) out[x] = joined[faint_label[x]] ? 255 : 0;
  }
  return intruders;
}

}  // namespace billiard::estimator
