#include "estimator/ball_scale.h"

#include <algorithm>
#include <cmath>

namespace billiard::estimator {

std::optional<BallScale> ScaleFromOutlines(const TableRegion& table,
                                           const std::vector<BallOutline>& outlines) {
  // Each outline's radius at the table's centre (log), weighed by how much of it was seen.
  std::vector<std::pair<double, double>> logs;
  for (const BallOutline& outline : outlines) {
    const double depth = table.InverseDepthAt(outline.centre);
    if (depth > 0 && outline.radius > 0) {
      logs.push_back({std::log(outline.radius / depth), outline.supporting_rays});
    }
  }
  if (logs.empty()) return std::nullopt;
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
    if (below >= 0.5 * heaviest) return BallScale{table.inverse_depth, std::exp(value)};
  }
  return BallScale{table.inverse_depth, std::exp(group.back().first)};
}

BallScale ScaleFromTable(const TableRegion& table, double ball_to_table_width) {
  return BallScale{table.inverse_depth,
                   ball_to_table_width * table.PixelsPerWidthAt(table.Centre())};
}

}  // namespace billiard::estimator
