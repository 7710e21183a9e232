#include "estimator/ball_outline.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace billiard::estimator {

namespace {

// Along a ray, samples every kRayStepPx from kRayFrom to kRayTo radii; an edge candidate is a
// local maximum of the colour's rate of change of at least kEdgeOfRayMax of the ray's largest.
constexpr double kRayStepPx = 0.5;
constexpr double kRayFrom = 0.5, kRayTo = 1.5;
constexpr double kEdgeOfRayMax = 0.25;
// The window holds every ray from a centre that may move a radius.
constexpr double kWindowRadii = 2.6;
constexpr int kWindowMarginPx = 2;
// The fit: a candidate counts when within kCandidateReach radii of the circle; Tukey's constant
// on the robust scale (never below kMinScalePx); the prior on the radius weighs as much as
// kRadiusPriorRays rays; up to kIterations Gauss-Newton steps, ended by a step below kStepPx.
constexpr double kCandidateReach = 0.35;
constexpr double kTukey = 4.685;
constexpr double kMinScalePx = 0.4;
constexpr double kRadiusPriorRays = 2.0;
constexpr int kIterations = 8;
constexpr double kStepPx = 1e-3;
constexpr int kMinCandidateRays = 6;
// A fit that moves more than kMaxShiftRadii or changes the radius by more than kMaxRadiusChange
// (relative) found something else.
constexpr double kMaxShiftRadii = 1.0, kMaxRadiusChange = 0.4;
// A ray supports the circle with an edge within max(kSupportPx, kSupportRadii r) of it.
constexpr double kSupportPx = 1.0, kSupportRadii = 0.08;

// The window's colours in float L*a*b* (L* 0..100).
struct LabWindow {
  cv::Mat lab;
  Eigen::Vector2d origin;
  // Bilinear colour at a frame pixel; false outside the window.
  bool At(const Eigen::Vector2d& pixel, cv::Vec3f* colour) const {
    const double x = pixel.x() - origin.x(), y = pixel.y() - origin.y();
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= lab.cols || y0 + 1 >= lab.rows) return false;
    const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
    const auto* r0 = lab.ptr<cv::Vec3f>(y0);
    const auto* r1 = lab.ptr<cv::Vec3f>(y0 + 1);
    *colour = (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) +
              fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
    return true;
  }
};

std::optional<LabWindow> WindowAround(const cv::Mat& bgr, const Eigen::Vector2d& centre,
                                      double radius) {
  const int half = static_cast<int>(std::ceil(kWindowRadii * radius)) + kWindowMarginPx;
  const cv::Rect rect = cv::Rect(static_cast<int>(std::lround(centre.x())) - half,
                                 static_cast<int>(std::lround(centre.y())) - half, 2 * half + 1,
                                 2 * half + 1) &
                        cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (rect.width < 3 || rect.height < 3) return std::nullopt;
  LabWindow window;
  cv::Mat scaled;
  bgr(rect).convertTo(scaled, CV_32F, 1.0 / 255);
  cv::cvtColor(scaled, window.lab, cv::COLOR_BGR2Lab);
  window.origin = {rect.x, rect.y};
  return window;
}

// The places along each ray from `centre` where the colour changes fastest (frame pixels), and
// how fast; rays that leave the window have none.
using RayEdges = std::vector<std::pair<Eigen::Vector2d, double>>;

std::array<RayEdges, kOutlineRays> EdgesAlongRays(const LabWindow& window,
                                                  const Eigen::Vector2d& centre, double radius,
                                                  double min_edge) {
  std::array<RayEdges, kOutlineRays> edges;
  const double from = kRayFrom * radius;
  const int samples = static_cast<int>((kRayTo - kRayFrom) * radius / kRayStepPx) + 1;
  std::vector<cv::Vec3f> colour(samples);
  std::vector<double> rate(samples, 0.0);
  for (int k = 0; k < kOutlineRays; ++k) {
    const double angle = 2 * M_PI * k / kOutlineRays;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    bool inside = true;
    for (int i = 0; i < samples && inside; ++i) {
      inside = window.At(centre + (from + i * kRayStepPx) * direction, &colour[i]);
    }
    if (!inside) continue;
    double largest = 0;
    for (int i = 1; i + 1 < samples; ++i) {
      const cv::Vec3f d = colour[i + 1] - colour[i - 1];
      rate[i] = std::sqrt(d.dot(d)) / (2 * kRayStepPx);
      largest = std::max(largest, rate[i]);
    }
    for (int i = 2; i + 2 < samples; ++i) {
      if (rate[i] < min_edge || rate[i] < kEdgeOfRayMax * largest || rate[i] < rate[i - 1] ||
          rate[i] < rate[i + 1]) {
        continue;
      }
      // The peak of the parabola through the maximum and its neighbours.
      const double curvature = rate[i - 1] - 2 * rate[i] + rate[i + 1];
      double offset = curvature < 0 ? 0.5 * (rate[i - 1] - rate[i + 1]) / curvature : 0.0;
      offset = std::clamp(offset, -1.0, 1.0);
      edges[k].push_back({centre + (from + (i + offset) * kRayStepPx) * direction, rate[i]});
    }
  }
  return edges;
}

// The circle through the candidate of each ray nearest it, by IRLS from (centre, radius), with
// the radius pulled towards `expected`. False when too few rays have a candidate near it.
bool FitCircle(const std::array<RayEdges, kOutlineRays>& edges, double expected,
               Eigen::Vector2d* centre, double* radius) {
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    std::vector<Eigen::Vector2d> points;
    std::vector<double> residuals;
    for (const RayEdges& ray : edges) {
      double nearest = kCandidateReach * expected;
      const Eigen::Vector2d* chosen = nullptr;
      for (const auto& [point, rate] : ray) {
        const double distance = std::abs((point - *centre).norm() - *radius);
        if (distance < nearest) {
          nearest = distance;
          chosen = &point;
        }
      }
      if (chosen == nullptr) continue;
      points.push_back(*chosen);
      residuals.push_back((*chosen - *centre).norm() - *radius);
    }
    if (static_cast<int>(points.size()) < kMinCandidateRays) return false;
    std::vector<double> magnitudes(residuals.size());
    std::transform(residuals.begin(), residuals.end(), magnitudes.begin(),
                   [](double r) { return std::abs(r); });
    std::nth_element(magnitudes.begin(), magnitudes.begin() + magnitudes.size() / 2,
                     magnitudes.end());
    const double scale = std::max(kMinScalePx, 1.4826 * magnitudes[magnitudes.size() / 2]);
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double u = residuals[i] / (kTukey * scale);
      if (std::abs(u) >= 1) continue;
      const double weight = (1 - u * u) * (1 - u * u);
      const Eigen::Vector2d d = points[i] - *centre;
      const double n = d.norm();
      if (n < 1e-9) continue;
      const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);
      normal += weight * j * j.transpose();
      gradient += weight * j * residuals[i];
    }
    normal(2, 2) += kRadiusPriorRays;
    gradient(2) += kRadiusPriorRays * (*radius - expected);
    const Eigen::Vector3d step = -normal.ldlt().solve(gradient);
    if (!step.allFinite()) return false;
    *centre += step.head<2>();
    *radius += step.z();
    if (step.norm() < kStepPx) break;
  }
  return true;
}

// How the fitted circle is supported: rays with an edge of at least `min_edge` on it.
void MeasureSupport(const LabWindow& window, double expected, double min_edge,
                    BallOutline* outline) {
  const double band = std::max(kSupportPx, kSupportRadii * expected);
  std::vector<double> angles;
  double strength = 0;
  for (int k = 0; k < kOutlineRays; ++k) {
    const double angle = 2 * M_PI * k / kOutlineRays;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    double best = 0;
    for (double rho = outline->radius - band; rho <= outline->radius + band; rho += kRayStepPx) {
      cv::Vec3f inner, outer;
      if (!window.At(outline->centre + (rho - 0.5) * direction, &inner) ||
          !window.At(outline->centre + (rho + 0.5) * direction, &outer)) {
        continue;
      }
      const cv::Vec3f d = outer - inner;
      best = std::max(best, static_cast<double>(std::sqrt(d.dot(d))));
    }
    if (best >= min_edge) {
      angles.push_back(angle);
      strength += best;
    }
  }
  outline->supporting_rays = static_cast<int>(angles.size());
  outline->edge_strength = angles.empty() ? 0.0 : strength / angles.size();
  outline->largest_gap = 2 * M_PI;
  if (angles.empty()) return;
  outline->largest_gap = 2 * M_PI - (angles.back() - angles.front());
  for (std::size_t i = 1; i < angles.size(); ++i) {
    outline->largest_gap = std::max(outline->largest_gap, angles[i] - angles[i - 1]);
  }
}

}  // namespace

std::optional<BallOutline> FitBallOutline(const cv::Mat& bgr, const Eigen::Vector2d& start,
                                          double radius, double min_edge) {
  const std::optional<LabWindow> window = WindowAround(bgr, start, radius);
  if (!window || !(radius > 0)) return std::nullopt;
  Eigen::Vector2d centre = start;
  double fitted = radius;
  for (int round = 0; round < 2; ++round) {
    const auto edges = EdgesAlongRays(*window, centre, radius, min_edge);
    if (!FitCircle(edges, radius, &centre, &fitted)) return std::nullopt;
    if ((centre - start).norm() > kMaxShiftRadii * radius ||
        std::abs(fitted - radius) > kMaxRadiusChange * radius) {
      return std::nullopt;
    }
  }
  BallOutline outline;
  outline.centre = centre;
  outline.radius = fitted;
  MeasureSupport(*window, radius, min_edge, &outline);
  return outline;
}

}  // namespace billiard::estimator
