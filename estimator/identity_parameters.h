// What ball identity (ball_identity.h) is told rather than measures in a frame: the colour each
// class of ball may have, and the shares of a ball's disc that make it the cue ball, a black ball
// or a stripe. They are data, not geometry: the defaults were set by hand (the colours read from
// manufacturers' product pictures, the shares on rendered balls and on the dev frames, issue 27),
// and identity_fit.h fits them from balls whose classes are known, which is how
// `billiard bench-detect --cross-validate` measures whether they transfer to cameras they were
// not fitted on (issue 45).
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_class.h"

namespace billiard::estimator {

class IdentityClassifier;  // identity_classifier.h

// A colour a class of ball may have: its CIE L*a*b* under white light (after a frame's white
// balance), in the colour table of `table`: kPool (the solids 1-7, whose stripes 9-15 share their
// colours), kSnooker, or kCarom, whose red and yellow English pool's (kBlackball) share. A class
// may have several colours, the nearest counting: sets differ (pool's 4 is purple, or pink in TV
// sets).
struct ColourPrototype {
  BallSet table = BallSet::kPool;
  BallClass ball_class = BallClass::kUnknown;
  cv::Vec3f lab;
};

// The colour table a set's classes are looked up in: carom's for English pool (its reds and
// yellows are carom's), the set's own otherwise.
BallSet ColourTableOf(BallSet set);

// The class whose colour a ball of `ball_class` of `set` has: a pool stripe's is its solid's (the
// 11's is the 3's), every other class's its own.
BallClass ColourClassOf(BallClass ball_class, BallSet set);

struct IdentityParameters {
  std::vector<ColourPrototype> colours;
  // Shares of a ball's disc (ball_identity.h): the cue ball is at least `cue_white` white with at
  // most `cue_colour` coloured, and a coloured ball at least `cue_colour` coloured; a black ball
  // at least `black_share` black, and a coloured one at most; a pool ball at least `stripe_plain`
  // plain over nearly its whole disc a stripe, else a solid.
  double cue_white = 0.6, cue_colour = 0.2;
  double black_share = 0.5;
  double stripe_plain = 0.3;
  // A learnt classifier (identity_classifier.h): where it knows the ball set, its costs replace
  // the shares' and colours' above (`--identity model`); none, the rules decide (`rules`).
  std::shared_ptr<const IdentityClassifier> classifier;
};

// The parameters set by hand: the colours of Aramith's pool and snooker sets and of carom balls
// (sRGB read from the manufacturers' product pictures, converted to L*a*b*), a TV set's pink 4
// and a brown 7 beside the purple and the maroon, and the shares above.
const IdentityParameters& HandSetIdentity();

// The L*a*b* (OpenCV's float conversion) of an sRGB colour given as R, G, B.
cv::Vec3f LabOfSrgb(const cv::Vec3b& srgb);

}  // namespace billiard::estimator
