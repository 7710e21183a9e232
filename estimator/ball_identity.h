// Which ball a detection is: the cue ball, the black, and the colour class (pool balls by number,
// solids and stripes; snooker's reds and colours; carom's white, yellow and red), with a
// confidence.
//
// A ball's disc (inside the blur of its outline) holds three kinds of pixels, told apart in CIE
// L*a*b* after the frame's white balance is corrected:
//   - white: little chroma and bright (the cue ball, a stripe's caps, a number's disc);
//   - black: little chroma and dark (the eight ball, the snooker black, a number's figure);
//   - plain: white at any shade (its chroma small against its lightness: a stripe's cap turned
//     away from the light is dark grey) or black;
//   - coloured: the rest, whose median colour is the ball's colour.
// The white balance comes from the frame itself: the ball with the largest share of nearly grey,
// bright pixels is taken for the cue ball (every game has one, and it is the only ball that is
// white all over), and the frame's colours are scaled per channel so that its pixels that are not
// clipped are grey (von Kries 1902). A frame without such a ball keeps its colours.
//
// Then, per ball set:
//   - the cue ball is mostly white, with no colour of its own;
//   - a black ball is mostly black;
//   - otherwise the coloured pixels' median is compared with each colour of the set (kBallColours,
//     approximate L*a*b* of the balls under white light), weighting hue over lightness (shading
//     changes the lightness across a ball, and the camera's exposure all of it); for pool, a ball
//     that is a large share plain (kStripePlain) out to nearly its outline (a stripe turned band
//     on shows its caps only at the limb) is a stripe (9-15), else a solid (1-7); a ball with no
//     colour in its disc and a stripe's plain share may be a stripe seen cap on, outlined along
//     its cap's edge: its colour is read from the ring just outside, the cloth's colour left out.
// The classes are given all at once, the rack's count of each respected (assignment.h). The
// confidence is how clearly the ball is what it was called, in [0, 1]: how much more the whole
// assignment would cost were the ball not of its class, against its class's cost (a ratio). It is
// the rack's margin, not the ball's alone: of two red solids alike, neither is sure which is the 3;
// a pale red stripe whose other fit, the 3, is plainly another ball's is sure it is the 11.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"

namespace billiard::estimator {

struct BallIdentity {
  BallClass ball_class = BallClass::kUnknown;
  double confidence = 0;  // 0..1
};

// The identity of each ball of a BGR frame, in the order of `balls`.
std::vector<BallIdentity> IdentifyBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                        BallSet set);

}  // namespace billiard::estimator
