// One ball's outline refined to sub-pixel from a prediction (a search peak, or a track's
// prediction): the window around it, the centre pulled onto the ball, the outline fitted by a
// robust circle through the edge along rays, and a score of how ball-like it is. Internal to the
// estimator's detector (ball_detector.h).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>

#include "estimator/ball_detector.h"
#include "estimator/local_cloth.h"

namespace billiard::estimator::internal {

// The ball near `predicted` (radius about r pixels) in `bgr` against one local cloth colour;
// std::nullopt when none is there or it scores below min_score.
std::optional<BallDetection> RefineBall(const cv::Mat& bgr, const Eigen::Vector2d& predicted,
                                        double r, const LocalCloth& cloth, double min_score);

}  // namespace billiard::estimator::internal
