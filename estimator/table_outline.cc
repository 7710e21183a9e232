#include "estimator/table_outline.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "estimator/table_finder.h"

namespace billiard::estimator {

namespace {

// The outline's band: kOutlineBandPx either side of the cloth's outline at
// the table search's resolution (the frame's longer side at most kTableSearchSize pixels).
constexpr int kOutlineBandPx = 3;

int OutlineFactor(const cv::Size& size) {
  return static_cast<int>(std::ceil(std::max(size.width, size.height) / kTableSearchSize));
}

// The gradient magnitude of a frame's grey levels at the table search's resolution.
cv::Mat OutlineGradient(const cv::Mat& bgr) {
  const int factor = OutlineFactor(bgr.size());
  cv::Mat small, grey, gx, gy, magnitude;
  cv::resize(bgr, small, {}, 1.0 / factor, 1.0 / factor, cv::INTER_AREA);
  cv::cvtColor(small, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_32F);
  cv::Sobel(grey, gx, CV_32F, 1, 0);
  cv::Sobel(grey, gy, CV_32F, 0, 1);
  cv::magnitude(gx, gy, magnitude);
  return magnitude;
}

}  // namespace

TableOutline::TableOutline(const cv::Mat& bgr, const std::array<Eigen::Vector2d, 4>& cloth_corners)
    : gradient_(OutlineGradient(bgr)), band_(cv::Mat::zeros(gradient_.size(), CV_8U)) {
  std::vector<cv::Point> outline;
  const double factor = OutlineFactor(bgr.size());
  for (const auto& c : cloth_corners) {
    outline.emplace_back(static_cast<int>(std::lround((c.x() + 0.5) / factor - 0.5)),
                         static_cast<int>(std::lround((c.y() + 0.5) / factor - 0.5)));
  }
  cv::polylines(band_, outline, true, 255, 2 * kOutlineBandPx + 1);
}

double TableOutline::Agreement(const cv::Mat& bgr) const {
  if (empty()) return 1.0;
  const cv::Mat now = OutlineGradient(bgr);
  const cv::Scalar mean_then = cv::mean(gradient_, band_);
  const cv::Scalar mean_now = cv::mean(now, band_);
  double both = 0, then_squares = 0, now_squares = 0;
  for (int y = 0; y < now.rows; ++y) {
    const auto* band = band_.ptr<uint8_t>(y);
    const auto* a = gradient_.ptr<float>(y);
    const auto* b = now.ptr<float>(y);
    for (int x = 0; x < now.cols; ++x) {
      if (!band[x]) continue;
      const double da = a[x] - mean_then[0], db = b[x] - mean_now[0];
      both += da * db;
      then_squares += da * da;
      now_squares += db * db;
    }
  }
  return then_squares > 0 && now_squares > 0 ? both / std::sqrt(then_squares * now_squares) : 0.0;
}

}  // namespace billiard::estimator
