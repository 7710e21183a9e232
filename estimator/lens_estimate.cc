#include "estimator/lens_estimate.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "sim/physics/golden_section.h"

namespace billiard::estimator {

namespace {

// Newton's iterations inverting the distortion's cubic (monotone from r_image: it converges in a
// few), and when they stop.
constexpr int kNewtonIterations = 30;
// The standard deviation of normal errors over their median absolute value.
constexpr double kMadToSigma = 1.4826;
constexpr double kNewtonTolerancePx = 1e-9;
// The grid over the k1 range, and the bracket golden-section search (Kiefer 1953) narrows the
// grid's best to within a step of it.
constexpr int kGridSteps = 120;
constexpr double kGoldenBracket = 1e-6;
// The pinhole canvas holds the sides' points' box widened by this share of it on each side: the
// points stop short of the table's corners (the corner pockets are left out).
constexpr double kCanvasMargin = 0.15;
// The canvas is at most this many times the frame's size along each axis.
constexpr double kMaxCanvasScale = 2.0;

// The distortion's coefficient per squared pixel.
double Kappa(const RadialLens& lens) { return lens.k1 / (lens.focal_px * lens.focal_px); }

// The pinhole radius whose image is at `image_radius`; for a barrel lens at most the fold's.
double UndistortedRadius(double kappa, double image_radius) {
  if (kappa < 0) {
    const double fold = 1.0 / std::sqrt(-3.0 * kappa);
    if (image_radius >= 2.0 / 3.0 * fold) return fold;
  }
  double r = image_radius;
  for (int i = 0; i < kNewtonIterations; ++i) {
    const double step = (r + kappa * r * r * r - image_radius) / (1.0 + 3.0 * kappa * r * r);
    r -= step;
    if (std::abs(step) < kNewtonTolerancePx) break;
  }
  return r;
}

// Whether every point is inside the radius a barrel lens folds back at (a k1 that cannot have
// produced the points).
bool InsideFold(const RadialLens& lens, const std::vector<Eigen::Vector2d>& points) {
  const double kappa = Kappa(lens);
  if (kappa >= 0) return true;
  const double fold_image_radius = 2.0 / 3.0 / std::sqrt(-3.0 * kappa);
  for (const auto& p : points) {
    if ((p - lens.centre).norm() >= fold_image_radius) return false;
  }
  return true;
}

// The total-least-squares line through points: (unit normal, offset) with normal . p = offset.
std::pair<Eigen::Vector2d, double> FitLine(const std::vector<Eigen::Vector2d>& points) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(scatter);
  const Eigen::Vector2d normal = solver.eigenvectors().col(0);
  return {normal, normal.dot(mean)};
}

// A side's squared residuals [image px^2] through `lens`, those within kLensOutlierSigmas robust
// standard deviations (1.4826 median absolute residuals, at least half an outline pixel) of a line
// fitted to all, then again of the line fitted to those kept.
std::vector<double> KeptSquaredResiduals(const RadialLens& lens,
                                         const std::vector<Eigen::Vector2d>& side,
                                         double outline_px) {
  std::vector<Eigen::Vector2d> pinhole;
  for (const auto& p : side) pinhole.push_back(lens.ToPinhole(p));
  std::vector<double> errors(pinhole.size());
  const auto keep = [&](const std::pair<Eigen::Vector2d, double>& line) {
    for (std::size_t i = 0; i < pinhole.size(); ++i) {
      errors[i] =
          std::abs(line.first.dot(pinhole[i]) - line.second) * lens.MagnificationAt(pinhole[i]);
    }
    std::vector<double> sorted = errors;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double sigma = std::max(kMadToSigma * sorted[sorted.size() / 2], 0.5 * outline_px);
    std::vector<std::size_t> kept;
    for (std::size_t i = 0; i < errors.size(); ++i) {
      if (errors[i] <= kLensOutlierSigmas * sigma) kept.push_back(i);
    }
    return kept;
  };
  std::vector<Eigen::Vector2d> inliers;
  for (const std::size_t i : keep(FitLine(pinhole))) inliers.push_back(pinhole[i]);
  std::vector<double> squares;
  for (const std::size_t i : keep(FitLine(inliers))) squares.push_back(errors[i] * errors[i]);
  return squares;
}

// The sides' robust RMS residual [image px] through `lens`; infinite where the lens cannot have
// made the points.
double SidesResidual(const RadialLens& lens,
                     const std::array<std::vector<Eigen::Vector2d>, 4>& sides, double outline_px) {
  double squares = 0;
  std::size_t count = 0;
  for (const auto& side : sides) {
    if (side.size() < kLensMinSidePoints) continue;
    if (!InsideFold(lens, side)) return std::numeric_limits<double>::infinity();
    for (const double s : KeptSquaredResiduals(lens, side, outline_px)) {
      squares += s;
      ++count;
    }
  }
  return std::sqrt(squares / std::max<std::size_t>(1, count));
}

// Whether `lens` leaves no side more bent than through a pinhole, nor than the grid's rounding
// can explain (kLensMinBow): a lens straightens every side, and a side nearly through the image
// centre stays straight. A kink in one side (balls over a cushion, a pocket's jaws seen from a
// low camera) is no lens: the k1 that halves it bends the other sides.
bool BendsNoSide(const RadialLens& lens, const std::array<std::vector<Eigen::Vector2d>, 4>& sides,
                 double outline_px) {
  const auto rms = [&](const RadialLens& through, const std::vector<Eigen::Vector2d>& side) {
    const std::vector<double> squares = KeptSquaredResiduals(through, side, outline_px);
    double sum = 0;
    for (const double s : squares) sum += s;
    return std::sqrt(sum / std::max<std::size_t>(1, squares.size()));
  };
  RadialLens pinhole = lens;
  pinhole.k1 = 0;
  const double straight = kLensMinBow * kGridNoise * outline_px;
  for (const auto& side : sides) {
    if (side.size() < kLensMinSidePoints) continue;
    if (rms(lens, side) > std::max(rms(pinhole, side), straight)) return false;
  }
  return true;
}

// The best k1 in the range: the grid's best, refined by golden-section search within a step of it.
double BestK1(RadialLens lens, const std::array<std::vector<Eigen::Vector2d>, 4>& sides,
              double outline_px) {
  const auto residual = [&](double k1) {
    lens.k1 = k1;
    return SidesResidual(lens, sides, outline_px);
  };
  const double step = (kLensK1Max - kLensK1Min) / kGridSteps;
  double best = 0, best_residual = residual(0);
  for (int i = 0; i <= kGridSteps; ++i) {
    const double k1 = kLensK1Min + i * step, r = residual(k1);
    if (r < best_residual) best = k1, best_residual = r;
  }
  const double refined =
      physics::GoldenSectionMinimum(residual, best - step, best + step,
                                    [](double lo, double hi) { return hi - lo < kGoldenBracket; });
  return residual(refined) < best_residual ? refined : best;
}

// The canvas holding the sides' pinhole images, widened by kCanvasMargin, at most kMaxCanvasScale
// of the frame.
void FitCanvas(const std::array<std::vector<Eigen::Vector2d>, 4>& sides, const cv::Size& size,
               RadialLens* lens) {
  Eigen::Vector2d low = Eigen::Vector2d::Constant(HUGE_VAL), high = -low;
  for (const auto& side : sides) {
    for (const auto& p : side) {
      const Eigen::Vector2d q = lens->ToPinhole(p);
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
    }
  }
  const Eigen::Vector2d margin = kCanvasMargin * (high - low);
  const Eigen::Vector2d largest(kMaxCanvasScale * size.width, kMaxCanvasScale * size.height);
  const Eigen::Vector2d extent = (high - low + 2 * margin).cwiseMin(largest);
  const Eigen::Vector2d middle = 0.5 * (low + high);
  lens->canvas_origin = (middle - 0.5 * extent).array().floor();
  lens->canvas =
      cv::Size(static_cast<int>(std::ceil(extent.x())), static_cast<int>(std::ceil(extent.y())));
}

}  // namespace

Eigen::Vector2d RadialLens::ToPinhole(const Eigen::Vector2d& image_px) const {
  if (IsPinhole()) return image_px;
  const Eigen::Vector2d d = image_px - centre;
  const double r = d.norm();
  const double scale = r > 0 ? UndistortedRadius(Kappa(*this), r) / r : 1.0;
  return centre + scale * d - canvas_origin;
}

Eigen::Vector2d RadialLens::ToImage(const Eigen::Vector2d& pinhole_px) const {
  if (IsPinhole()) return pinhole_px;
  const Eigen::Vector2d d = pinhole_px + canvas_origin - centre;
  return centre + d * (1.0 + Kappa(*this) * d.squaredNorm());
}

double RadialLens::MagnificationAt(const Eigen::Vector2d& pinhole_px) const {
  if (IsPinhole()) return 1.0;
  const double r2 = (pinhole_px + canvas_origin - centre).squaredNorm(), kappa = Kappa(*this);
  return std::max(1.0 + kappa * r2, 1.0 + 3.0 * kappa * r2);
}

cv::Mat RadialLens::Undistort(const cv::Mat& image) const {
  if (IsPinhole()) return image;
  cv::Mat map_x(canvas, CV_32F), map_y(canvas, CV_32F);
  for (int y = 0; y < canvas.height; ++y) {
    for (int x = 0; x < canvas.width; ++x) {
      const Eigen::Vector2d p = ToImage(Eigen::Vector2d(x, y));
      map_x.at<float>(y, x) = static_cast<float>(p.x());
      map_y.at<float>(y, x) = static_cast<float>(p.y());
    }
  }
  cv::Mat pinhole;
  cv::remap(image, pinhole, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT,
            cv::Scalar::all(0));
  return pinhole;
}

LensEstimate EstimateRadialLens(const std::array<std::vector<Eigen::Vector2d>, 4>& sides,
                                const cv::Size& size, double outline_px) {
  LensEstimate estimate;
  int counted = 0;
  for (const auto& side : sides) counted += side.size() >= kLensMinSidePoints;
  if (counted < 2) return estimate;
  RadialLens lens;
  lens.focal_px = kLensFocalWidths * size.width;
  lens.centre = Eigen::Vector2d(0.5 * (size.width - 1), 0.5 * (size.height - 1));
  estimate.pinhole_rms_px = SidesResidual(lens, sides, outline_px);
  estimate.best_rms_px = estimate.pinhole_rms_px;
  const double grid = kGridNoise * outline_px;
  // Sides straight within the outline's rounding are a pinhole's: no k1 to search (nearly every
  // frame, and the search is most of the estimate's time).
  if (estimate.pinhole_rms_px <= kLensMinBow * grid) return estimate;
  estimate.best_k1 = BestK1(lens, sides, outline_px);
  lens.k1 = estimate.best_k1;
  estimate.best_rms_px = SidesResidual(lens, sides, outline_px);
  const auto excess = [&](double rms) { return std::sqrt(std::max(0.0, rms * rms - grid * grid)); };
  if (excess(estimate.best_rms_px) > kLensGain * excess(estimate.pinhole_rms_px)) return estimate;
  if (!BendsNoSide(lens, sides, outline_px)) return estimate;
  FitCanvas(sides, size, &lens);
  estimate.lens = lens;
  return estimate;
}

}  // namespace billiard::estimator
