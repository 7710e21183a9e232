#include "estimator/ball_refinement.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace billiard::estimator::internal {

namespace {

constexpr int kRays = 32;

inline float Bilinear(const cv::Mat& m, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  if (x0 < 0 || y0 < 0 || x0 + 1 >= m.cols || y0 + 1 >= m.rows) return -1.0f;
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float* r0 = m.ptr<float>(y0);
  const float* r1 = m.ptr<float>(y0 + 1);
  return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) +
         fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

struct CircleFit {
  Eigen::Vector2d centre;
  double radius = 0;
  int inliers = 0;
  double largest_gap = 2 * M_PI;  // largest angle [rad] between neighbouring inlier rays
};

// Least-squares circle (geometric distance, Gauss-Newton) through the edge points, refitted
// without the points farther than a robust bound from the first fit.
CircleFit FitCircle(const std::vector<Eigen::Vector2d>& points, const std::vector<double>& angles,
                    const Eigen::Vector2d& start, double start_radius) {
  CircleFit fit{start, start_radius, 0, 2 * M_PI};
  std::vector<bool> use(points.size(), true);
  for (int round = 0; round < 2; ++round) {
    for (int iteration = 0; iteration < 6; ++iteration) {
      Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
      Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!use[i]) continue;
        const Eigen::Vector2d d = points[i] - fit.centre;
        const double n = d.norm();
        if (n < 1e-9) continue;
        const Eigen::Vector3d j(-d.x() / n, -d.y() / n, -1.0);
        jtj += j * j.transpose();
        jtr += j * (n - fit.radius);
      }
      if (jtj.determinant() < 1e-9) return fit;
      const Eigen::Vector3d step = -jtj.ldlt().solve(jtr);
      fit.centre += step.head<2>();
      fit.radius += step.z();
      if (step.norm() < 1e-4) break;
    }
    std::vector<double> residuals;
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (use[i]) residuals.push_back(std::abs((points[i] - fit.centre).norm() - fit.radius));
    }
    if (residuals.empty()) return fit;
    std::nth_element(residuals.begin(), residuals.begin() + residuals.size() / 2, residuals.end());
    const double bound = std::max(0.75, 3.0 * 1.4826 * residuals[residuals.size() / 2]);
    for (std::size_t i = 0; i < points.size(); ++i) {
      use[i] = std::abs((points[i] - fit.centre).norm() - fit.radius) <= bound;
    }
  }
  std::vector<double> inlier_angles;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (use[i]) inlier_angles.push_back(angles[i]);
  }
  fit.inliers = static_cast<int>(inlier_angles.size());
  if (!inlier_angles.empty()) {
    std::sort(inlier_angles.begin(), inlier_angles.end());
    fit.largest_gap = 2 * M_PI - (inlier_angles.back() - inlier_angles.front());
    for (std::size_t i = 1; i < inlier_angles.size(); ++i) {
      fit.largest_gap = std::max(fit.largest_gap, inlier_angles[i] - inlier_angles[i - 1]);
    }
  }
  return fit;
}

// RefineBall's geometry, in radii r of the expected ball unless said otherwise.
// The search window reaches past the rays; the contrast is computed in the disc (plus a pixel)
// that the rays and the centroid reach, the rest of the window stays cloth (0).
constexpr double kWindowRadii = 1.7;
constexpr int kWindowMarginPx = 2;
constexpr double kContrastRadii = 1.65;
// A prediction off by up to a radius is pulled onto the ball by centroid steps of the ballness in
// a disc; with less ballness there than this fraction of a ball's area pi r^2, no ball is there.
constexpr int kPullSteps = 3;
constexpr double kPullRadii = 1.2;
constexpr double kMinBallnessArea = 0.3;
// Rays from the centre, sampled every kRayStepPx from kRayStart to kRayEnd radii; a sample whose
// contrast is below kClothContrast is cloth; the rim is the kRimWidthPx inside the outline, past
// the blur (and a camera's glow) of the outline; an edge lies between kMinEdge and kMaxEdge radii,
// and at least a kMinEdgeRayFraction of the rays must find one.
constexpr double kRayStepPx = 0.75;
constexpr double kRayStart = 0.3, kRayEnd = 1.6;
constexpr float kClothContrast = 0.5f;
constexpr double kRimWidthPx = 4.0;
constexpr double kMinEdge = 0.6, kMaxEdge = 1.4;
constexpr int kMinEdgeRayFraction = 3;  // 1 / 3
// The score's terms, each from 0 to 1: the fraction of the rays on the fitted circle (a ramp),
// and no gap between them wider than kMaxInlierGap; the fitted radius within kRadiusTolerance
// (relative) of the expected; the disc of kFilledRadii ball-coloured on average (a ramp); and for
// a ball brighter than the cloth, the rim band darker than the core as on a sphere lit from above
// (a ramp of their ratio) or a hue of its own in the core (a ramp).
constexpr double kRoundStart = 0.35, kRoundWidth = 0.35;
constexpr double kMaxInlierGap = 1.15 * M_PI;
constexpr double kRadiusTolerance = 0.3;
constexpr double kFilledRadii = 0.7;
constexpr double kFilledStart = 0.5, kFilledWidth = 0.3;
constexpr double kCoreRadii = 0.5, kRimBandFrom = 0.65, kRimBandTo = 0.9;
constexpr double kSphereRimToCore = 0.97, kSphereWidth = 0.1;
constexpr double kOwnHueStart = 0.5, kOwnHueWidth = 0.2;

// 0 below `start`, rising linearly to 1 at start + width.
double Ramp(double x, double start, double width) {
  return std::clamp((x - start) / width, 0.0, 1.0);
}

// The pixels around a prediction: their contrast against the local cloth, unclipped (for the
// edges) and clipped to 1 (the ballness), in a window of the frame.
struct BallWindow {
  cv::Rect rect;
  cv::Mat contrast, ballness;
  Eigen::Vector2d origin() const { return {rect.x, rect.y}; }
};

std::optional<BallWindow> WindowAround(const cv::Mat& bgr, const Eigen::Vector2d& predicted,
                                       double r, const LocalCloth& cloth) {
  const int half = static_cast<int>(std::ceil(kWindowRadii * r)) + kWindowMarginPx;
  BallWindow w;
  w.rect =
      cv::Rect(static_cast<int>(std::lround(predicted.x())) - half,
               static_cast<int>(std::lround(predicted.y())) - half, 2 * half + 1, 2 * half + 1) &
      cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (w.rect.width < 3 || w.rect.height < 3) return std::nullopt;
  w.contrast = cv::Mat::zeros(w.rect.size(), CV_32F);
  w.ballness = cv::Mat::zeros(w.rect.size(), CV_32F);
  const double reach = kContrastRadii * r + 1;
  const Eigen::Vector2d local = predicted - w.origin();
  for (int y = 0; y < w.rect.height; ++y) {
    const double dy = y - local.y();
    if (std::abs(dy) > reach) continue;
    const double dx = std::sqrt(reach * reach - dy * dy);
    const int from = std::max(0, static_cast<int>(local.x() - dx));
    const int to = std::min(w.rect.width - 1, static_cast<int>(local.x() + dx) + 1);
    const auto* in = bgr.ptr<cv::Vec3b>(w.rect.y + y) + w.rect.x;
    float* c = w.contrast.ptr<float>(y);
    float* clipped = w.ballness.ptr<float>(y);
    for (int x = from; x <= to; ++x) {
      float s, e;
      Decompose(cv::Vec3f(in[x][0], in[x][1], in[x][2]), cloth, &s, &e);
      c[x] = Contrast(s, e, cloth);
      clipped[x] = std::min(1.0f, c[x]);
    }
  }
  return w;
}

// `centre` (window pixels) moved onto the ball by centroid steps of the ballness; nothing when
// hardly anything there is ball-like.
std::optional<Eigen::Vector2d> PullOntoBall(const cv::Mat& ballness, Eigen::Vector2d centre,
                                            double r) {
  const double reach = kPullRadii * r;
  for (int step = 0; step < kPullSteps; ++step) {
    double sw = 0, sx = 0, sy = 0;
    for (int y = std::max(0, static_cast<int>(centre.y() - reach));
         y <= std::min(ballness.rows - 1, static_cast<int>(centre.y() + reach)); ++y) {
      for (int x = std::max(0, static_cast<int>(centre.x() - reach));
           x <= std::min(ballness.cols - 1, static_cast<int>(centre.x() + reach)); ++x) {
        if ((Eigen::Vector2d(x, y) - centre).squaredNorm() > reach * reach) continue;
        const double w = ballness.at<float>(y, x);
        sw += w;
        sx += w * x;
        sy += w * y;
      }
    }
    if (sw < kMinBallnessArea * M_PI * r * r) return std::nullopt;
    centre = {sx / sw, sy / sw};
  }
  return centre;
}

// The distance from `centre` of the ball's edge along one ray: where the contrast falls to half
// the level of the ball's rim on that ray, i.e. where the pixel is half ball, half cloth,
// whatever the ball's colour and however blurred the frame. Nothing when the ray ends in
// something else or finds no edge where one may be. `profile` is scratch space.
std::optional<double> EdgeAlongRay(const cv::Mat& contrast, const Eigen::Vector2d& centre,
                                   const Eigen::Vector2d& direction, double r,
                                   std::vector<float>* profile) {
  const std::size_t rim_samples = static_cast<std::size_t>(std::ceil(kRimWidthPx / kRayStepPx));
  profile->clear();
  for (double rho = kRayStart * r; rho <= kRayEnd * r; rho += kRayStepPx) {
    const Eigen::Vector2d p = centre + rho * direction;
    const float value = Bilinear(contrast, p.x(), p.y());
    if (value < 0) break;  // left the window or the frame
    profile->push_back(value);
  }
  const std::vector<float>& v = *profile;
  // From outside in, so that reflections inside the ball do not end it early; a ray that ends in
  // something else (a touching ball, an arm) has no edge of this ball.
  if (v.empty() || v.back() >= kClothContrast) return std::nullopt;
  std::size_t outer = v.size() - 1;
  while (outer > 0 && v[outer - 1] < kClothContrast) --outer;
  if (outer < rim_samples + 1) return std::nullopt;
  // The ball's level on this ray is its rim's, just inside the outline: shading, highlights and
  // a paler centre (a pink ball) differ from ray to ray, and a level taken elsewhere would move
  // the half-way point in or out with them, the centre with it.
  const float half_level =
      0.5f * *std::max_element(v.begin() + (outer - rim_samples), v.begin() + outer);
  std::size_t i = outer - rim_samples;
  while (i < v.size() && v[i] >= half_level) ++i;
  if (i >= v.size() || i == 0) return std::nullopt;
  const double edge = kRayStart * r + kRayStepPx * (i - (half_level - v[i]) / (v[i - 1] - v[i]));
  if (!(edge > kMinEdge * r && edge < kMaxEdge * r)) return std::nullopt;
  return edge;
}

// The ball's outline: a circle fitted to the edges along half the rays, to bring the centre
// close, then along all of them from there (each then crosses the edge square on).
std::optional<CircleFit> FitOutline(const cv::Mat& contrast, const Eigen::Vector2d& centre,
                                    double r) {
  CircleFit fit{centre, r, 0, 2 * M_PI};
  std::vector<float> profile;
  for (const int rays : {kRays / 2, kRays}) {
    std::vector<Eigen::Vector2d> points;
    std::vector<double> angles;
    for (int k = 0; k < rays; ++k) {
      const double angle = 2 * M_PI * k / rays;
      const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
      if (auto edge = EdgeAlongRay(contrast, fit.centre, direction, r, &profile)) {
        points.push_back(fit.centre + *edge * direction);
        angles.push_back(angle);
      }
    }
    if (static_cast<int>(points.size()) < rays / kMinEdgeRayFraction) return std::nullopt;
    fit = FitCircle(points, angles, fit.centre, fit.radius);
  }
  return fit;
}

// What makes the outline a ball, 0..1: round, of the expected radius, filled, and shaded like a
// sphere when brighter than the cloth; nothing when the disc holds no pixels to judge by.
std::optional<double> BallScore(const cv::Mat& bgr, const BallWindow& w, const CircleFit& fit,
                                double r, const LocalCloth& cloth) {
  const double round = Ramp(static_cast<double>(fit.inliers) / kRays, kRoundStart, kRoundWidth) *
                       (fit.largest_gap < kMaxInlierGap ? 1.0 : 0.0);
  const double q = (fit.radius - r) / r;
  const double size = std::clamp(1.0 - (q / kRadiusTolerance) * (q / kRadiusTolerance), 0.0, 1.0);
  double inside = 0, inside_n = 0, core = 0, core_tint = 0, core_n = 0, rim = 0, rim_n = 0;
  const int x0 = std::max(0, static_cast<int>(fit.centre.x() - fit.radius));
  const int x1 = std::min(w.rect.width - 1, static_cast<int>(fit.centre.x() + fit.radius) + 1);
  const int y0 = std::max(0, static_cast<int>(fit.centre.y() - fit.radius));
  const int y1 = std::min(w.rect.height - 1, static_cast<int>(fit.centre.y() + fit.radius) + 1);
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const double rho = std::hypot(x - fit.centre.x(), y - fit.centre.y()) / fit.radius;
      if (rho < kFilledRadii) {
        inside += w.ballness.at<float>(y, x);
        ++inside_n;
      }
      if (rho >= kRimBandTo || (rho >= kCoreRadii && rho <= kRimBandFrom)) continue;
      const cv::Vec3b p = bgr.at<cv::Vec3b>(w.rect.y + y, w.rect.x + x);
      float s, e;
      Decompose(cv::Vec3f(p[0], p[1], p[2]), cloth, &s, &e);
      if (rho < kCoreRadii) {
        core += s;
        core_tint += e * (1.0f / kMinAcross);  // in absolute terms: noise is no hue
        ++core_n;
      } else {
        rim += s;
        ++rim_n;
      }
    }
  }
  if (inside_n == 0 || core_n == 0 || rim_n == 0) return std::nullopt;
  const double filled = Ramp(inside / inside_n, kFilledStart, kFilledWidth);
  // Only what is brighter than the cloth can be light projected on it, so darker balls need no
  // more. Light takes the cloth's tint and lights it evenly; a ball brighter than the cloth is
  // either of another hue (a white ball is whiter than any cloth) or darkens towards its outline
  // as a sphere lit from above does (even when the camera saturates its centre: then it is white).
  core /= core_n;
  core_tint /= core_n;
  rim /= rim_n;
  const double sphere = Ramp(kSphereRimToCore - rim / core, 0.0, kSphereWidth);
  const double own_hue = Ramp(core_tint, kOwnHueStart, kOwnHueWidth);
  const double shading = core <= 1.0 ? 1.0 : std::max(sphere, own_hue);
  return round * size * filled * shading;
}

}  // namespace

std::optional<BallDetection> RefineBall(const cv::Mat& bgr, const Eigen::Vector2d& predicted,
                                        double r, const LocalCloth& cloth, double min_score) {
  const std::optional<BallWindow> window = WindowAround(bgr, predicted, r, cloth);
  if (!window) return std::nullopt;
  const auto centre = PullOntoBall(window->ballness, predicted - window->origin(), r);
  if (!centre) return std::nullopt;
  const std::optional<CircleFit> fit = FitOutline(window->contrast, *centre, r);
  if (!fit) return std::nullopt;
  const std::optional<double> score = BallScore(bgr, *window, *fit, r, cloth);
  if (!score || *score < min_score) return std::nullopt;
  return BallDetection{fit->centre + window->origin(), fit->radius, *score};
}

}  // namespace billiard::estimator::internal
