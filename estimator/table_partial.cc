#include "estimator/table_partial.h"

#include <Eigen/Geometry>
#include <cmath>

namespace billiard::estimator {

namespace {

// Whether a point is within `border_px` of edge `edge` (0 left, 1 top, 2 right, 3 bottom).
bool OnEdge(const Eigen::Vector2d& p, int edge, const cv::Size& size, double border_px) {
  switch (edge) {
    case 0: return p.x() <= border_px;
    case 1: return p.y() <= border_px;
    case 2: return p.x() >= size.width - 1 - border_px;
    default: return p.y() >= size.height - 1 - border_px;
  }
}

// How far [px] along a side, from its seen end, a distance `t` [px of the seen end's scale] on the
// table is seen, the side's vanishing point `vanishing` away (negative: behind; see the header).
double SeenDistance(double t, double vanishing) {
  return std::isfinite(vanishing) ? t / (1.0 + t / vanishing) : t;
}

// The rectangle whose seen part is `corners`, cut along side `cut`, its unseen side `ratio` times
// the seen opposite side's length from it (CompletedAcrossBorder, with the ratio of one reading).
std::optional<std::array<Eigen::Vector2d, 4>> ExtendedAcrossBorder(
    const std::array<Eigen::Vector2d, 4>& corners, int cut, double ratio) {
  // Side cut + 1 runs from the border to the seen side, side cut + 3 from the seen side back to it.
  const int border_a = (cut + 1) % 4, end_a = (cut + 2) % 4;
  const int end_b = (cut + 3) % 4, border_b = cut;
  const double opposite = (corners[end_a] - corners[end_b]).norm();
  const Eigen::Vector3d meet =
      corners[end_a].homogeneous().cross(corners[border_a].homogeneous())
          .cross(corners[end_b].homogeneous().cross(corners[border_b].homogeneous()));
  std::array<Eigen::Vector2d, 4> whole = corners;
  double seen_share = 0;
  for (const auto& [end, border] : {std::pair{end_a, border_a}, std::pair{end_b, border_b}}) {
    const Eigen::Vector2d seen = corners[border] - corners[end];
    const Eigen::Vector2d along = seen.normalized();
    double vanishing = HUGE_VAL;
    if (std::abs(meet.z()) > 1e-12 * meet.head<2>().norm()) {
      vanishing = (meet.hnormalized() - corners[end]).dot(along);
    }
    const double length = ratio * opposite;
    if (std::isfinite(vanishing) && 1.0 + length / vanishing <= 0) return std::nullopt;
    const double far = SeenDistance(length, vanishing);
    if (seen.norm() >= far) return std::nullopt;
    seen_share += 0.5 * seen.norm() / far;
    whole[border] = corners[end] + far * along;
  }
  if (seen_share < kMinSeenShare) return std::nullopt;
  return whole;
}

}  // namespace

std::vector<int> SidesAlongBorder(const std::array<Eigen::Vector2d, 4>& corners,
                                  const cv::Size& size, double border_px) {
  std::vector<int> along;
  for (int i = 0; i < 4; ++i) {
    for (int edge = 0; edge < 4; ++edge) {
      if (OnEdge(corners[i], edge, size, border_px) &&
          OnEdge(corners[(i + 1) % 4], edge, size, border_px)) {
        along.push_back(i);
        break;
      }
    }
  }
  return along;
}

std::optional<std::array<Eigen::Vector2d, 4>> CompletedAcrossBorder(
    const std::array<Eigen::Vector2d, 4>& corners, int cut, double aspect) {
  for (const double ratio : {aspect, 1.0 / aspect}) {
    if (const auto whole = ExtendedAcrossBorder(corners, cut, ratio)) return whole;
  }
  return std::nullopt;
}

}  // namespace billiard::estimator
