#include "estimator/outline_stretches.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

namespace billiard::estimator {

namespace {

// Each side is fitted to the outline points within kSideBand of the hull's perimeter of it and
// between kSideEnd and 1 - kSideEnd along it (the corner pockets and their jaws are outside);
// RANSAC keeps the points within kRansacInlierPx (search px).
constexpr double kSideBand = 0.02;
constexpr double kSideEnd = 0.12;
constexpr double kRansacInlierPx = 1.5;
constexpr int kRansacTries = 200;
// Up to kMaxStretches lines are fitted to a side's outline points, each through kMinStretch of them
// at least (but the first): the straight stretches of a side that an arm, a cue or the cushion's
// top breaks (FitSides).
constexpr std::size_t kMaxStretches = 3;
constexpr double kMinStretch = 0.1;
constexpr double kMaxStretchTurn = 0.15;  // [rad] from the hull's side
// The first line kept may turn twice as far: the hull's side is itself turned where a vertex of its
// quadrilateral is off a corner (a pocket, an arm across it), by 0.155 rad on a dev frame
// (fou_03's left side), where balls in a row against a short side seen from low make a line
// turned by 0.38 rad (the hard suite's 15-degree camera).
constexpr double kMaxFirstStretchTurn = 2 * kMaxStretchTurn;

// The least-squares line through `points` and their distances from it.
Line LeastSquaresLine(const std::vector<cv::Point2f>& points) {
  cv::Vec4f fitted;
  cv::fitLine(points, fitted, cv::DIST_L2, 0, 0.01, 0.01);
  Line line;
  line.coefficients = {-fitted[1], fitted[0], fitted[1] * fitted[2] - fitted[0] * fitted[3]};
  double squares = 0;
  for (const auto& p : points) {
    const double e = line.coefficients.dot(Eigen::Vector3d(p.x, p.y, 1));
    squares += e * e;
  }
  line.points = static_cast<int>(points.size());
  line.rms = std::sqrt(squares / points.size());
  return line;
}

}  // namespace

std::vector<cv::Point2d> SidePoints(const std::vector<cv::Point>& outline, const cv::Point2d& a,
                                    const cv::Point2d& b, double perimeter) {
  const cv::Point2d along = b - a;
  const double length = cv::norm(along);
  if (length < 1) return {};
  const cv::Point2d u = along / length, normal(-u.y, u.x);
  std::vector<cv::Point2d> points;
  for (const cv::Point& p : outline) {
    const cv::Point2d q = cv::Point2d(p) - a;
    const double t = q.dot(u) / length;
    if (t > kSideEnd && t < 1 - kSideEnd && std::abs(q.dot(normal)) < kSideBand * perimeter) {
      points.push_back(p);
    }
  }
  return points;
}

std::vector<Line> FitSides(const std::vector<cv::Point>& outline, const cv::Point2d& a,
                           const cv::Point2d& b, double perimeter) {
  const cv::Point2d along = b - a;
  const double length = cv::norm(along);
  if (length < 1) return {};
  const cv::Point2d u = along / length;
  std::vector<cv::Point2d> points = SidePoints(outline, a, b, perimeter);
  const double min_points = std::max(2.0, kMinStretch * static_cast<double>(points.size()));
  std::vector<Line> lines;
  std::vector<cv::Point2f> turned;  // the first stretch's points, where it is turned
  std::mt19937 random(1);
  for (std::size_t tries = 0; tries < kMaxStretches && points.size() >= min_points; ++tries) {
    std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
    Eigen::Vector3d best_line = Eigen::Vector3d::Zero();
    int best_count = 0;
    for (int attempt = 0; attempt < kRansacTries; ++attempt) {
      const cv::Point2d p1 = points[pick(random)], p2 = points[pick(random)];
      const cv::Point2d d = p2 - p1;
      const double n = cv::norm(d);
      if (n < 5) continue;
      const Eigen::Vector3d line(-d.y / n, d.x / n, (d.y * p1.x - d.x * p1.y) / n);
      int count = 0;
      for (const auto& p : points) {
        count += std::abs(line.dot(Eigen::Vector3d(p.x, p.y, 1))) < kRansacInlierPx;
      }
      if (count > best_count) {
        best_count = count;
        best_line = line;
      }
    }
    std::vector<cv::Point2f> inliers;
    std::vector<cv::Point2d> rest;
    for (const auto& p : points) {
      if (std::abs(best_line.dot(Eigen::Vector3d(p.x, p.y, 1))) < kRansacInlierPx) {
        inliers.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
      } else {
        rest.push_back(p);
      }
    }
    if (inliers.size() < std::max<std::size_t>(2, lines.empty() ? 2 : min_points)) break;
    points = std::move(rest);
    // A stretch turned from the side (an arm's edge, a cue's, balls' in a row against a cushion
    // seen from low) is none of it; the first one turned is kept for when no other is found.
    const double turn = std::abs(best_line.x() * u.x + best_line.y() * u.y);
    if (turn > std::sin(lines.empty() ? kMaxFirstStretchTurn : kMaxStretchTurn)) {
      if (lines.empty() && turned.empty()) turned = inliers;
      continue;
    }
    lines.push_back(LeastSquaresLine(inliers));
  }
  if (lines.empty() && !turned.empty()) lines.push_back(LeastSquaresLine(turned));
  return lines;
}

}  // namespace billiard::estimator
