#include "estimator/ball_scale.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "estimator/lab_image.h"
#include "estimator/not_cloth.h"

namespace billiard::estimator {

namespace {

// The balls' scale is measured on the compact blobs of not-cloth (not_cloth.h): blobs of at least
// kMinBlobArea of its pixels, about as wide as high (kMaxBlobAspect), filling at least
// kMinBlobFill of their bounding ellipse; their outlines count with kMinScaleSupport of the rays.
constexpr int kMinBlobArea = 12;
constexpr double kMaxBlobAspect = 1.55;
constexpr double kMinBlobFill = 0.75;
constexpr double kMinScaleSupport = 0.35;

// How much wider than its playing surface a found table may be: the finder's sides are the
// cushions' noses, a few pixels out at most; a tenth covers that and a perspective's rounding.
constexpr double kTableWidthTolerance = 1.1;

// The outlines of the compact blobs of not-cloth on the table: mostly single balls, whose radii
// give the scale.
std::vector<BallOutline> BlobOutlines(const cv::Mat& bgr, const TableRegion& table,
                                      const ClothModel& cloth) {
  const NotClothMap not_cloth(bgr, table, cloth, NotClothMap::BlobFactor(table));
  if (not_cloth.mask().empty()) return {};
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(not_cloth.mask(), labels, stats, centroids, 8);
  const LabImage lab(bgr, not_cloth.region());
  std::vector<BallOutline> outlines;
  for (int i = 1; i < n; ++i) {
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    const double aspect = static_cast<double>(std::max(w, h)) / std::min(w, h);
    const double fill = area / (0.25 * M_PI * w * h);
    if (area < kMinBlobArea || aspect > kMaxBlobAspect || fill < kMinBlobFill) continue;
    const Eigen::Vector2d centroid(centroids.at<double>(i, 0), centroids.at<double>(i, 1));
    const auto outline =
        FitBallOutline(lab, not_cloth.ToFull(centroid), not_cloth.factor() * std::sqrt(area / M_PI),
                       EdgeThreshold(cloth.edge_noise));
    if (outline && outline->supporting_rays >= kMinScaleSupport * kOutlineRays) {
      outlines.push_back(*outline);
    }
  }
  return outlines;
}

}  // namespace

double LargestTableRatio(BallSet set) {
  // Ball radius over playing-surface width on the largest regulation table: pool, the WPA's 9-ft
  // (50 in wide, balls 2 1/4 in); snooker, the WPBSA's 12-ft (1778 mm, balls 52.5 mm); carom,
  // the UMB's match table (1.42 m, balls 61.5 mm); blackball, the WEPF's 7-ft (0.94 m, balls 2 in).
  switch (set) {
    case BallSet::kSnooker:
      return 0.02625 / 1.778;
    case BallSet::kCarom:
      return 0.03075 / 1.42;
    case BallSet::kBlackball:
      return 0.0254 / 0.94;
    case BallSet::kPool:
      break;
  }
  return 0.028575 / 1.27;
}

double LeastPlausibleScale(const TableRegion& table, BallSet set) {
  return LargestTableRatio(set) * table.PixelsPerWidthAt(table.Centre()) / kTableWidthTolerance;
}

std::optional<BallScale> ScaleFromOutlines(const TableRegion& table,
                                           const std::vector<BallOutline>& outlines,
                                           double least_plausible) {
  // Each outline's radius at the table's centre (log), weighed by how much of it was seen.
  std::vector<std::pair<double, double>> logs;
  for (const BallOutline& outline : outlines) {
    const double depth = table.InverseDepthAt(outline.centre);
    if (depth > 0 && outline.radius > 0) {
      logs.push_back({std::log(outline.radius / depth), outline.supporting_rays});
    }
  }
  if (logs.empty()) return std::nullopt;
  // The groups are seeded by the plausible outlines where there are any.
  const auto is_plausible = [&](double log_radius) {
    return std::exp(log_radius) >= least_plausible;
  };
  const bool any_plausible = std::any_of(logs.begin(), logs.end(),
                                         [&](const auto& v) { return is_plausible(v.first); });
  // A scale the table does not allow is no measurement: the pieces of a rack that the cloth's
  // colour breaks up, with no ball lying apart.
  if (least_plausible > 0 && !any_plausible) return std::nullopt;
  const double agreement = std::log(kScaleAgreement);
  const auto agreeing_with = [&](double seed) {
    std::vector<std::pair<double, double>> group;
    std::copy_if(logs.begin(), logs.end(), std::back_inserter(group),
                 [&](const auto& v) { return std::abs(v.first - seed) < agreement; });
    return group;
  };
  const auto weight = [](const std::vector<std::pair<double, double>>& group) {
    double sum = 0;
    for (const auto& [value, w] : group) sum += w;
    return sum;
  };
  double seed = logs.front().first, heaviest = 0;
  for (const auto& [value, w] : logs) {
    if (any_plausible && !is_plausible(value)) continue;
    const double agreeing = weight(agreeing_with(value));
    if (agreeing > heaviest) {
      heaviest = agreeing;
      seed = value;
    }
  }
  // The weighted median of the heaviest agreeing group.
  auto group = agreeing_with(seed);
  std::sort(group.begin(), group.end());
  double below = 0;
  for (const auto& [value, w] : group) {
    below += w;
    if (below >= 0.5 * heaviest) return BallScale{table.inverse_depth, std::exp(value), heaviest};
  }
  return BallScale{table.inverse_depth, std::exp(group.back().first), heaviest};
}

BallScale ScaleFromTable(const TableRegion& table, double ball_to_table_width) {
  return BallScale{table.inverse_depth,
                   ball_to_table_width * table.PixelsPerWidthAt(table.Centre())};
}

std::optional<BallScale> ScaleFromBlobs(const cv::Mat& bgr, const TableRegion& table,
                                        const ClothModel& cloth, double least_plausible) {
  return ScaleFromOutlines(table, BlobOutlines(bgr, table, cloth), least_plausible);
}

}  // namespace billiard::estimator
