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
// Then, per ball set (the shares and colours are IdentityParameters, identity_parameters.h):
//   - the cue ball is mostly white, with no colour of its own;
//   - a black ball is mostly black;
//   - otherwise the coloured pixels' median is compared with each colour of the set (approximate
//     L*a*b* of the balls under white light), weighting hue over lightness (shading changes the
//     lightness across a ball, and the camera's exposure all of it); for pool, a ball that is a
//     large share plain (stripe_plain) out to nearly its outline (a stripe turned band on shows
//     its caps only at the limb) is a stripe (9-15), else a solid (1-7); a ball with no colour in
//     its disc and a stripe's plain share may be a stripe seen cap on, outlined along its cap's
//     edge: its colour is read from the ring just outside, the cloth's colour left out.
// The classes are given all at once, the rack's count of each respected (assignment.h). The
// confidence is how clearly the ball is what it was called, in [0, 1]: how much more the whole
// assignment would cost were the ball not of its class, against its class's cost (a ratio). It is
// the rack's margin, not the ball's alone: of two red solids alike, neither is sure which is the 3;
// a pale red stripe whose other fit, the 3, is plainly another ball's is sure it is the 11.
//
// The identity is read in two steps: what each ball shows (LookAtBalls: its shares and colours,
// which no parameter changes), then what it is (NameBalls: the costs and the assignment, under
// the parameters), so that parameters can be fitted and compared on the looks of labelled balls
// without reading the frames again (identity_fit.h).
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "estimator/identity_parameters.h"

namespace billiard::estimator {

struct BallIdentity {
  BallClass ball_class = BallClass::kUnknown;
  double confidence = 0;  // 0..1
};

// What a ball shows, after the frame's white balance: the shares of its disc's pixels that are
// white, black and coloured, the share of plain pixels over nearly the whole ball, and the
// colours read (CIE L*a*b*).
struct BallLook {
  bool seen = false;  // any pixel of its disc in the frame
  double white = 0, black = 0, plain = 0, colour = 0;
  std::optional<cv::Vec3f> disc_colour;  // the median of the disc's coloured pixels, if any
  // A pool ball's: the median colour of the ring just outside its outline, the cloth left out,
  // where enough of it is coloured (a stripe seen cap on shows its band there).
  std::optional<cv::Vec3f> band_colour;
  // The descriptor a learnt classifier reads (ball_features.h), under the same white balance.
  std::vector<float> features;
};

// What each ball of a BGR frame shows, in the order of `balls`; the ring beyond the outline is
// read for the pool set only.
std::vector<BallLook> LookAtBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                  BallSet set);

// The colour a ball is judged by: its disc's, or, where its disc has less colour than the cue
// ball may have and a stripe's plain share, the band beyond its cap; none when neither was read.
std::optional<cv::Vec3f> JudgedColour(const BallLook& look, const IdentityParameters& parameters);

// The identity of each ball from its look (`looks` parallel to `balls`, whose scores say how much
// leaving each unnamed costs), all at once with the rack's count of each class; each class's cost
// the parameters' classifier's where it knows the set, else the rules'.
std::vector<BallIdentity> NameBalls(const std::vector<BallLook>& looks,
                                    const std::vector<BallDetection>& balls, BallSet set,
                                    const IdentityParameters& parameters);

// The identity of each ball of a BGR frame, in the order of `balls`: NameBalls of LookAtBalls.
std::vector<BallIdentity> IdentifyBalls(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                                        BallSet set,
                                        const IdentityParameters& parameters = HandSetIdentity());

}  // namespace billiard::estimator
