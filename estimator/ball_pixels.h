// Internal to ball identity (ball_identity.h, ball_features.h): a ball's pixels read from a frame
// and the kinds of pixel a ball's surface shows, in CIE L*a*b* after the frame's white balance.
#pragma once

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_detector.h"

namespace billiard::estimator {

// A pixel is grey when its chroma (sqrt(a*^2 + b*^2)) is below kGreyChroma; grey and at least
// kWhiteLightness (after the white balance brings the cue ball to L* 90) it is white, grey and
// at most kBlackLightness black.
inline constexpr double kGreyChroma = 16.0;
inline constexpr double kWhiteLightness = 65.0, kBlackLightness = 30.0;
// A pixel is plain (Plain) when its chroma is below kPlainSaturation of its L*.
inline constexpr double kPlainSaturation = 0.3;

inline double Chroma(const cv::Vec3f& lab) { return std::hypot(lab[1], lab[2]); }

// Plain: a white surface at any shade, its chroma below kPlainSaturation of its lightness, or
// black. Shade scales a surface's L*, a* and b* alike (each about the cube root of the light it
// gets), so their ratio, the saturation (Fairchild 2013), is what shade leaves of a colour: a
// stripe's white cap turned away from the light is dark grey, not black and not white, and an
// ivory cap or a cue ball under warm light is pale but far less saturated than any coloured ball.
inline bool Plain(const cv::Vec3f& lab) {
  const double chroma = Chroma(lab);
  return chroma < kPlainSaturation * lab[0] || (chroma < kGreyChroma && lab[0] <= kBlackLightness);
}

// Calls visit(pixel, distance) for each of a ball's pixels (BGR, 0..1) within `radii` of its
// fitted radius, with its distance from the centre in pixels.
template <typename Visit>
void ForEachPixelWithin(const cv::Mat& bgr, const BallDetection& ball, double radii, Visit visit) {
  const double reach = radii * ball.radius_px;
  const int x0 = std::max(0, static_cast<int>(std::floor(ball.pixel.x() - reach)));
  const int x1 = std::min(bgr.cols - 1, static_cast<int>(std::ceil(ball.pixel.x() + reach)));
  const int y0 = std::max(0, static_cast<int>(std::floor(ball.pixel.y() - reach)));
  const int y1 = std::min(bgr.rows - 1, static_cast<int>(std::ceil(ball.pixel.y() + reach)));
  for (int y = y0; y <= y1; ++y) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = x0; x <= x1; ++x) {
      const double r = std::hypot(x - ball.pixel.x(), y - ball.pixel.y());
      if (r > reach) continue;
      visit(cv::Vec3f(row[x][0] / 255.0f, row[x][1] / 255.0f, row[x][2] / 255.0f), r);
    }
  }
}

// Pixels (BGR, 0..1) scaled per channel by `gain` (a von Kries white balance, clipped at 1) and
// converted to L*a*b*.
std::vector<cv::Vec3f> ToLab(const std::vector<cv::Vec3f>& bgr, const cv::Vec3f& gain);

}  // namespace billiard::estimator
