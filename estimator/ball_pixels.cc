#include "estimator/ball_pixels.h"

#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

std::vector<cv::Vec3f> ToLab(const std::vector<cv::Vec3f>& bgr, const cv::Vec3f& gain) {
  if (bgr.empty()) return {};
  cv::Mat pixels(static_cast<int>(bgr.size()), 1, CV_32FC3);
  for (std::size_t i = 0; i < bgr.size(); ++i) {
    const cv::Vec3f& p = bgr[i];
    pixels.at<cv::Vec3f>(static_cast<int>(i)) =
        cv::Vec3f(std::min(1.0f, p[0] * gain[0]), std::min(1.0f, p[1] * gain[1]),
                  std::min(1.0f, p[2] * gain[2]));
  }
  cv::Mat lab;
  cv::cvtColor(pixels, lab, cv::COLOR_BGR2Lab);
  return std::vector<cv::Vec3f>(lab.begin<cv::Vec3f>(), lab.end<cv::Vec3f>());
}

}  // namespace billiard::estimator
