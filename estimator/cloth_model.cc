#include "estimator/cloth_model.h"

#include <algorithm>

namespace billiard::estimator {

cv::Vec3f ClothModel::ColourAt(const Eigen::Vector2d& pixel) const {
  const double x = std::clamp(pixel.x() / cell - 0.5, 0.0, colour.cols - 1.0);
  const double y = std::clamp(pixel.y() / cell - 0.5, 0.0, colour.rows - 1.0);
  const int x0 = std::min(static_cast<int>(x), colour.cols - 2 < 0 ? 0 : colour.cols - 2);
  const int y0 = std::min(static_cast<int>(y), colour.rows - 2 < 0 ? 0 : colour.rows - 2);
  const int x1 = std::min(x0 + 1, colour.cols - 1), y1 = std::min(y0 + 1, colour.rows - 1);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  return (1 - fy) * ((1 - fx) * colour.at<cv::Vec3f>(y0, x0) + fx * colour.at<cv::Vec3f>(y0, x1)) +
         fy * ((1 - fx) * colour.at<cv::Vec3f>(y1, x0) + fx * colour.at<cv::Vec3f>(y1, x1));
}

}  // namespace billiard::estimator
