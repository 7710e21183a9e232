// What a learnt classifier (identity_classifier.h) is shown of a ball: a fixed-length descriptor of
// its surface that the frame's exposure and the light's colour change as little as can be, so
// that a classifier fitted on rendered balls transfers to cameras and lights it never saw.
//
// It is read from the ball's pixels within kFeatureRadii of its fitted radius, in CIE L*a*b* after
// the frame's white balance (the von Kries gains of ball_identity.h, which bring the frame's
// white references to grey), each pixel one of the kinds of ball_pixels.h:
//   - the hue histogram of its coloured (not plain) pixels: kHueBins bins around the a*b* plane,
//     each pixel split linearly between its two nearest bins, each bin the share of all pixels
//     (a histogram of hue rather than of a* and b*, because shade scales the chroma with the
//     lightness but leaves the hue: Fairchild 2013);
//   - the shares of white, black, plain and coloured pixels (as ball_identity.h reads them), and
//     of dark pixels of any chroma (below kBlackLightness: a black ball mirrors a blue cloth);
//   - the plain share in kRings rings from the centre out (a stripe's caps show toward the limb
//     when its band faces the camera, at the centre when a cap does; a number's circle anywhere);
//   - the median coloured pixel: its L* (/100, after the white balance set it against white),
//     its a* and b* over its L* (the direction and amount of its colour, which shade leaves), and
//     its saturation (chroma over L*).
// A ball without a pixel in the frame has every feature zero.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_detector.h"

namespace billiard::estimator {

inline constexpr int kHueBins = 12;
inline constexpr int kRings = 3;
// The hue histogram, five shares, the rings' plain shares, the median colour's four.
inline constexpr int kBallFeatureCount = kHueBins + 5 + kRings + 4;

// The descriptor of `ball` in BGR frame `bgr` under the white balance `gain` (per channel, B, G,
// R): kBallFeatureCount values.
std::vector<float> BallFeatures(const cv::Mat& bgr, const BallDetection& ball,
                                const cv::Vec3f& gain);

}  // namespace billiard::estimator
