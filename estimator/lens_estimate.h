// The camera's radial lens distortion estimated from the table itself: the plumb-line method.
//
// The table's sides are straight lines on the table, so through a pinhole they are straight lines
// in the image; a wide-angle lens bends them (barrel distortion bows a side of a table filling the
// frame by some 26 px at k1 = -0.3). The distortion is the one whose removal makes the points along
// each side most collinear (Brown 1971, "Close-range camera calibration"; Devernay and Faugeras
// 2001, "Straight lines have to be straight"). One coefficient is estimated: OpenCV's k1, the
// distortion centred at the image centre,
//
//   p_image = c + (p_pinhole - c) (1 + k1 |p_pinhole - c|^2 / f^2).
//
// A plumb line identifies k1 / f^2 only (a straight line's image depends on nothing else), so f is
// not estimated: it is taken to be the frame's width (kLensFocalWidths), and a camera whose focal
// length is f has OpenCV's k1 = RadialLens::k1 (f / width)^2.
//
// The search is 1-D: a grid over [kLensK1Min, kLensK1Max], then golden-section search around the
// grid's best. Each side's straightness is the RMS distance of its undistorted points from their
// line, in the image's pixels, over the points not far from it (kLensOutlierSigmas: a middle
// pocket's notch, an arm across the side, are left out). A lens is accepted only when the sides
// seen through a pinhole are clearly bent, and the lens clearly straightens them (kLensMinBow,
// kLensGain) and bends none of them more than a pinhole or the grid does (a lens straightens every
// side; an outline that turns a corner, seen from a low camera over a rack, is an L that a strong
// barrel nearly straightens at the other sides' cost): a pinhole frame keeps k1 = 0 and the table
// found exactly as before.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace billiard::estimator {

// The focal length assumed [frame widths] (see above: only k1 / f^2 is seen).
inline constexpr double kLensFocalWidths = 1.0;
// The k1 searched (at f = the frame's width): from a fisheye-like barrel to a mild pincushion.
inline constexpr double kLensK1Min = -0.8, kLensK1Max = 0.4;
// A side's straightness is measured on its points within this many robust standard deviations of
// its line: a middle pocket's notch and an arm across the side are left out, a smooth bow is not.
inline constexpr double kLensOutlierSigmas = 3.0;
// A straight edge's outline traced on a grid of pixels is off its line by the rounding alone:
// kGridNoise of a pixel RMS (uniform over a pixel, 1 / sqrt(12)). A lens is accepted when the
// pinhole's residual is at least kLensMinBow times that (a bend, not the grid), and the lens takes
// the residual's excess over the grid's (its RMS: sqrt(residual^2 - grid^2)) down to kLensGain of
// the pinhole's at most (three quarters of the excess variance explained by the one parameter).
inline constexpr double kGridNoise = 0.28867513459481287;
inline constexpr double kLensMinBow = 1.5;
inline constexpr double kLensGain = 0.5;

// Radial distortion about the image centre, and the pinhole frame the undistorted image is drawn in
// (its pixel (0, 0) at `canvas_origin` of the pinhole's coordinates, which are the image's where
// k1 = 0). With k1 = 0 (the default) both maps are the identity.
struct RadialLens {
  double k1 = 0.0;
  double focal_px = 1.0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d canvas_origin = Eigen::Vector2d::Zero();
  cv::Size canvas;  // the pinhole frame's size (empty where k1 = 0)

  bool IsPinhole() const { return k1 == 0.0; }
  // The pinhole frame's pixel of an image pixel, and back. Beyond the radius where a barrel lens
  // folds back (no pinhole point maps there) the fold's radius is taken.
  Eigen::Vector2d ToPinhole(const Eigen::Vector2d& image_px) const;
  Eigen::Vector2d ToImage(const Eigen::Vector2d& pinhole_px) const;
  // How much larger a small thing at a pinhole pixel looks in the image (the larger of the radial
  // and the tangential scale): 1 where k1 = 0.
  double MagnificationAt(const Eigen::Vector2d& pinhole_px) const;
  // The image redrawn as the pinhole sees it, in the canvas (black outside the image).
  cv::Mat Undistort(const cv::Mat& image) const;
};

struct LensEstimate {
  RadialLens lens;            // k1 = 0 unless accepted
  double pinhole_rms_px = 0;  // the sides' residual at k1 = 0 [image px]
  // The best k1 searched, accepted or not, and the residual there [image px]; searched only where
  // the sides are bent beyond the outline's rounding (else 0 and the pinhole's residual).
  double best_rms_px = 0;
  double best_k1 = 0;
};

// The lens of a `size` frame from the points along each side of the table (image px; a side with
// fewer than kLensMinSidePoints counts for nothing, and two sides at least must count), traced on a
// grid of `outline_px` image pixels. The canvas covers the points' pinhole images.
inline constexpr std::size_t kLensMinSidePoints = 10;
LensEstimate EstimateRadialLens(const std::array<std::vector<Eigen::Vector2d>, 4>& sides,
                                const cv::Size& size, double outline_px);

}  // namespace billiard::estimator
