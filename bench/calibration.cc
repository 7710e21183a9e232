#include "bench/calibration.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "planner/choice/scene_balls.h"
#include "sim/table/seeded_uniform.h"

namespace billiard::bench {

std::vector<table::SceneBall> WithSeededCueBall(const table::TableGeometry& table, double radius,
                                                std::vector<table::SceneBall> balls,
                                                std::uint64_t seed) {
  table::SeededUniform uniform(seed);
  for (;;) {
    const Eigen::Vector2d p(uniform.Between(0, table.length), uniform.Between(0, table.width));
    if (!table.OnSurface(p, 3 * radius)) continue;
    const bool clear = std::all_of(balls.begin(), balls.end(), [&](const auto& b) {
      return (b.state.template segment<2>(physics::kX) - p).norm() >= 4 * radius;
    });
    if (clear) return choice::WithCueBallAt(std::move(balls), p);
  }
}

int DecileOf(double predicted) {
  return std::min(kDeciles - 1, static_cast<int>(predicted * kDeciles));
}

std::vector<plot::ReliabilityBin> Deciles(const std::vector<CalibrationPoint>& points) {
  std::vector<plot::ReliabilityBin> bins(kDeciles);
  std::vector<double> predicted_sum(kDeciles, 0.0);
  std::vector<int> potted(kDeciles, 0);
  for (int i = 0; i < kDeciles; ++i) {
    bins[i].lo = i / double(kDeciles);
    bins[i].hi = (i + 1) / double(kDeciles);
  }
  for (const CalibrationPoint& p : points) {
    const int i = DecileOf(p.predicted);
    bins[i].count += p.executions;
    predicted_sum[i] += p.predicted * p.executions;
    potted[i] += p.potted;
  }
  for (int i = 0; i < kDeciles; ++i) {
    if (bins[i].count == 0) continue;
    bins[i].predicted = predicted_sum[i] / bins[i].count;
    bins[i].measured = static_cast<double>(potted[i]) / bins[i].count;
  }
  return bins;
}

nlohmann::json DecilesJson(const std::vector<CalibrationPoint>& points, bool* calibrated) {
  std::vector<int> choices(kDeciles, 0);
  for (const CalibrationPoint& p : points) ++choices[DecileOf(p.predicted)];
  nlohmann::json deciles = nlohmann::json::array();
  *calibrated = true;
  const std::vector<plot::ReliabilityBin> bins = Deciles(points);
  for (int i = 0; i < kDeciles; ++i) {
    const plot::ReliabilityBin& b = bins[i];
    const bool judged = b.count >= kJudgedCount;
    const bool within = std::abs(b.measured - b.predicted) <= kCalibrationTolerance;
    if (judged && !within) *calibrated = false;
    const double stderr_ = b.count > 0 ? std::sqrt(b.measured * (1 - b.measured) / b.count) : 0.0;
    deciles.push_back({{"lo", b.lo}, {"hi", b.hi}, {"count", b.count}, {"choices", choices[i]},
                       {"predicted", b.predicted}, {"measured", b.measured},
                       {"measured_stderr", stderr_}, {"judged", judged},
                       {"within_5_points", within}});
  }
  return deciles;
}

}  // namespace billiard::bench
