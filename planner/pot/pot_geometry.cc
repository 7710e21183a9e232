#include "planner/pot/pot_geometry.h"

#include <algorithm>
#include <cmath>

namespace billiard::pot {

namespace {

// Closer than the clearance by less than this [m] is touching, not in the way.
constexpr double kGraze = 1e-6;

}  // namespace

Eigen::Vector2d GhostBall(const Eigen::Vector2d& object, const Eigen::Vector2d& direction,
                          double radius) {
  return object - 2.0 * radius * direction;
}

double CutAngle(const Eigen::Vector2d& approach, const Eigen::Vector2d& departure) {
  return std::acos(std::clamp(approach.dot(departure), -1.0, 1.0));
}

int RailCount(const table::TableGeometry& table) {
  return static_cast<int>(table.lines.size() - 2 * table.pockets.size());
}

std::optional<Eigen::Vector2d> RailBounce(const table::TableGeometry& table, int rail,
                                          const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                          double radius) {
  const table::CushionLine& line = table.lines[static_cast<std::size_t>(rail)];
  const Eigen::Vector2d origin = line.a + radius * line.normal;  // on the offset line
  const double h_from = (from - origin).dot(line.normal);
  const double h_to = (to - origin).dot(line.normal);
  if (!(h_from > 0.0 && h_to > 0.0)) return std::nullopt;
  // The straight line from `from` to the mirror image of `to` meets the offset line where the
  // heights above it are split in proportion.
  const Eigen::Vector2d mirror = to - 2.0 * h_to * line.normal;
  const Eigen::Vector2d bounce = from + (mirror - from) * (h_from / (h_from + h_to));
  const Eigen::Vector2d along = line.b - line.a;
  const double s = (bounce - origin).dot(along) / along.squaredNorm();
  if (s < 0.0 || s > 1.0) return std::nullopt;
  return bounce;
}

std::vector<int> BallsAcross(const std::vector<table::SceneBall>& balls, const Eigen::Vector2d& a,
                             const Eigen::Vector2d& b, double clearance,
                             const std::vector<int>& ignore) {
  std::vector<int> across;
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  for (const table::SceneBall& ball : balls) {
    if (std::find(ignore.begin(), ignore.end(), ball.id) != ignore.end()) continue;
    const Eigen::Vector2d p = ball.state.head<2>();
    const double along = length2 > 0.0 ? (p - a).dot(ab) / length2 : 0.0;
    // A ball beside or behind the start is left behind by a ball leaving along the line; one
    // touching it there is grazed at most.
    if (!(along > 0.0)) continue;
    const double s = std::min(along, 1.0);
    if ((a + s * ab - p).norm() < clearance - kGraze) across.push_back(ball.id);
  }
  return across;
}

}  // namespace billiard::pot
