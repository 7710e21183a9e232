#include "estimator/ball_scale.h"

#include <algorithm>
#include <cmath>

namespace billiard::estimator {

std::optional<BallScale> ScaleFromOutlines(const TableRegion& table,
                                           const std::vector<BallOutline>& outlines) {
  std::vector<double> logs;  // of each outline's radius at the table's centre
  for (const BallOutline& outline : outlines) {
    const double depth = table.InverseDepthAt(outline.centre);
    if (depth > 0 && outline.radius > 0) logs.push_back(std::log(outline.radius / depth));
  }
  if (logs.empty()) return std::nullopt;
  const double agreement = std::log(kScaleAgreement);
  std::size_t largest = 0;
  double seed = 0;
  for (const double candidate : logs) {
    const auto agreeing = static_cast<std::size_t>(std::count_if(
        logs.begin(), logs.end(), [&](double v) { return std::abs(v - candidate) < agreement; }));
    if (agreeing > largest) {
      largest = agreeing;
      seed = candidate;
    }
  }
  std::vector<double> group;
  std::copy_if(logs.begin(), logs.end(), std::back_inserter(group),
               [&](double v) { return std::abs(v - seed) < agreement; });
  std::nth_element(group.begin(), group.begin() + group.size() / 2, group.end());
  return BallScale{table.inverse_depth, std::exp(group[group.size() / 2])};
}

}  // namespace billiard::estimator
