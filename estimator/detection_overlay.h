// Detections drawn on the frame they were found in, for a person to look at: each ball's
// outline at its fitted radius, its centre, and its index, score and class beside it.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_detector.h"
#include "estimator/table_finder.h"

namespace billiard::estimator {

// A copy of `image` (BGR, or gray: drawn in colour) with `balls` drawn on it. The outline is
// green above score 0.5 and red below, so weak detections stand out.
cv::Mat DetectionOverlay(const cv::Mat& image, const std::vector<BallDetection>& balls);

// Draws the table found on a BGR image: the cloth's outline thin and grey-blue, the playing
// surface (the cushions' noses) in blue; through the lens it was found through, each side the
// curve that is its straight line's image.
void DrawTable(const TableRegion& table, cv::Mat* image);

}  // namespace billiard::estimator
