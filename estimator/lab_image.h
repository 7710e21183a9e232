// A frame in CIE L*a*b*, where the distance between two colours is about how different they look
// (Delta E 1976): the colour space every edge and colour difference of the detector is measured
// in. Stored as OpenCV's 8-bit L*a*b* (L* x 255 / 100, a* + 128, b* + 128), whose conversion is a
// table lookup, many times faster than the float one; read back in float L*a*b* units (L* 0..100,
// a*, b* about -128..127), interpolated between pixels.
//
// The detector reads a frame's colours only around the balls it outlines, a fraction of the
// table: tiles of kTilePx x kTilePx pixels are converted when first read.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace billiard::estimator {

class LabImage {
 public:
  static constexpr int kTilePx = 32;

  LabImage() = default;
  // The L*a*b* of a BGR (CV_8UC3) frame, or of `region` of it (whose pixels keep their frame
  // coordinates). The frame must outlive this.
  explicit LabImage(const cv::Mat& bgr, const cv::Rect& region = cv::Rect());

  // Float L*a*b* at a frame pixel, bilinear; false outside the region (colour untouched).
  bool At(const Eigen::Vector2d& pixel, cv::Vec3f* colour) const {
    const double x = pixel.x() - origin_.x, y = pixel.y() - origin_.y;
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= lab_.cols || y0 + 1 >= lab_.rows) return false;
    Convert(x0, y0);
    Convert(x0 + 1, y0);
    Convert(x0, y0 + 1);
    Convert(x0 + 1, y0 + 1);
    const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
    const auto* r0 = lab_.ptr<cv::Vec3b>(y0) + x0;
    const auto* r1 = lab_.ptr<cv::Vec3b>(y0 + 1) + x0;
    for (int c = 0; c < 3; ++c) {
      const float v = (1 - fy) * ((1 - fx) * r0[0][c] + fx * r0[1][c]) +
                      fy * ((1 - fx) * r1[0][c] + fx * r1[1][c]);
      (*colour)[c] = c == 0 ? v * kLightnessUnit : v - kChromaOffset;
    }
    return true;
  }
  // Float L*a*b* of the pixel at integer frame coordinates (x, y), which must be in the region.
  cv::Vec3f Pixel(int x, int y) const {
    Convert(x - origin_.x, y - origin_.y);
    const cv::Vec3b p = lab_.at<cv::Vec3b>(y - origin_.y, x - origin_.x);
    return {p[0] * kLightnessUnit, p[1] - kChromaOffset, p[2] - kChromaOffset};
  }
  // The region in frame coordinates.
  cv::Rect region() const { return {origin_, lab_.size()}; }
  // The 8-bit L*a*b* pixels of the region, all converted.
  const cv::Mat& pixels() const;
  bool empty() const { return lab_.empty(); }

  // 8-bit L*a*b* units: L* is stored times 255 / 100, a* and b* plus 128.
  static constexpr float kLightnessUnit = 100.0f / 255.0f;
  static constexpr float kChromaOffset = 128.0f;

 private:
  // Converts the tile holding region pixel (x, y) unless it is already.
  void Convert(int x, int y) const {
    const int tile = (y / kTilePx) * tiles_across_ + x / kTilePx;
    if (!converted_[tile]) ConvertTile(tile);
  }
  void ConvertTile(int tile) const;

  cv::Mat bgr_;  // the region of the frame
  mutable cv::Mat lab_;
  mutable std::vector<uint8_t> converted_;
  int tiles_across_ = 0;
  cv::Point origin_;
};

// The float L*a*b* of one BGR colour (0..255 per channel).
cv::Vec3f LabOf(const cv::Vec3f& bgr);

// OpenCV builds the tables of its 8-bit L*a*b* conversion on a process's first one (about 0.2 s
// on this machine). Builds them, once per process: at start-up, so that no frame waits for them.
void PrepareLabConversion();

}  // namespace billiard::estimator
