// Whether the camera still sees the table where it saw it when the table was learnt: the rails and
// pockets along the cloth's outline do not move when the balls do, so the colour gradients along
// the outline of two frames of one view agree, and stop agreeing once the camera has moved by
// more than the outline's band. The estimator asks this of each frame (OutlineAgreement of
// ball_detector.h) to learn the table again after a camera is knocked.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>

namespace billiard::estimator {

class TableOutline {
 public:
  // None: agrees with every frame.
  TableOutline() = default;

  // The outline of the cloth whose corners are `cloth_corners` [full-resolution px] in the BGR
  // frame `bgr`: its grey levels' gradient magnitude at the table search's resolution
  // (table_finder.h's kTableSearchSize on the longer side) and a band of 3 px either side of the
  // outline at that resolution.
  TableOutline(const cv::Mat& bgr, const std::array<Eigen::Vector2d, 4>& cloth_corners);

  // The normalized correlation of the learnt frame's and `bgr`'s gradients over the band: 1 for
  // the same view (or with no outline learnt), about 0 when the camera has moved by more than the
  // band. `bgr` is of the learnt frame's size.
  double Agreement(const cv::Mat& bgr) const;

  bool empty() const { return gradient_.empty(); }

 private:
  cv::Mat gradient_, band_;
};

}  // namespace billiard::estimator
