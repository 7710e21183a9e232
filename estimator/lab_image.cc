#include "estimator/lab_image.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace billiard::estimator {

LabImage::LabImage(const cv::Mat& bgr, const cv::Rect& region) {
  const cv::Rect area = region.empty() ? cv::Rect(0, 0, bgr.cols, bgr.rows)
                                       : region & cv::Rect(0, 0, bgr.cols, bgr.rows);
  if (area.empty()) return;
  bgr_ = bgr(area);
  lab_.create(area.size(), CV_8UC3);
  tiles_across_ = (area.width + kTilePx - 1) / kTilePx;
  converted_.assign(tiles_across_ * ((area.height + kTilePx - 1) / kTilePx), 0);
  origin_ = area.tl();
}

void LabImage::ConvertTile(int tile) const {
  const cv::Rect rect = cv::Rect((tile % tiles_across_) * kTilePx, (tile / tiles_across_) * kTilePx,
                                 kTilePx, kTilePx) &
                        cv::Rect(0, 0, lab_.cols, lab_.rows);
  cv::Mat out = lab_(rect);
  cv::cvtColor(bgr_(rect), out, cv::COLOR_BGR2Lab);
  converted_[tile] = 1;
}

const cv::Mat& LabImage::pixels() const {
  if (std::find(converted_.begin(), converted_.end(), 0) != converted_.end()) {
    cv::cvtColor(bgr_, lab_, cv::COLOR_BGR2Lab);
    std::fill(converted_.begin(), converted_.end(), 1);
  }
  return lab_;
}

cv::Vec3f LabOf(const cv::Vec3f& bgr) {
  const cv::Mat pixel(1, 1, CV_32FC3, cv::Scalar(bgr[0] / 255.0, bgr[1] / 255.0, bgr[2] / 255.0));
  cv::Mat lab;
  cv::cvtColor(pixel, lab, cv::COLOR_BGR2Lab);
  return lab.at<cv::Vec3f>(0, 0);
}

void PrepareLabConversion() {
  static const bool prepared = [] {
    cv::Mat lab;
    cv::cvtColor(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(0)), lab, cv::COLOR_BGR2Lab);
    return true;
  }();
  (void)prepared;
}

}  // namespace billiard::estimator
