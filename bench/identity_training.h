// Rendered balls whose classes are known, for fitting and testing the identity classifier
// (estimator/identity_classifier.h, `billiard train-identity`, issue 45): the classifier is fitted
// on these alone, so that the real frames stay test data.
//
// Each frame is one ball set's balls on a table rendered by sim/render (TableRenderer), every
// condition drawn from its own seed:
//   - the camera: looking at the table's middle from 25 to 85 degrees of elevation at any azimuth,
//     its field of view set so that a ball is 8 to 40 px across in radius;
//   - the balls: all of the set's (the cue ball left out of a quarter of the frames, so that the
//     white balance also meets frames without it), scattered where the camera sees them, each
//     turned at random (a stripe's band and a number's circle face the camera any way), each
//     class's colour one of the hand-set colours of identity_parameters.h (manufacturers'
//     pictures, never the dev frames) varied in lightness and chroma as sets differ;
//   - the light: its colour from daylight to tungsten with a tint either way (a camera's white
//     balance set for another light), its strength 45-125 %, its direction up to 35 degrees off
//     vertical, its ambient share and the balls' gloss; the cloth any hue, pale to dark;
//   - the camera's look: its colour response turned up to 20 degrees about the grey axis, a blur
//     of up to 1.2 px, sensor noise of 1-4 grey levels, JPEG at quality 40-95.
// Each ball is outlined where the camera projects it, its centre and radius perturbed as the
// detector's outlines are (kCentreJitter, kRadiusJitter), and looked at as the detector looks at
// its balls (estimator::LookAtBalls: the frame's white balance, then each ball's descriptor).
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "estimator/identity_classifier.h"

namespace billiard::bench {

struct IdentityTrainingOptions {
  int frames_per_set = 100;  // pool's; the other sets' in proportion to their classes
  std::uint64_t seed = 1;
  int width = 480, height = 360;  // of the rendered frames [px]
};

// One rendered frame, its balls outlined and their classes.
struct RenderedIdentityFrame {
  cv::Mat bgr;
  estimator::BallSet set = estimator::BallSet::kPool;
  std::vector<estimator::BallDetection> balls;
  std::vector<estimator::BallClass> classes;  // parallel to balls
};

// Frame `index` of `set` under `seed`: the same arguments give the same frame.
RenderedIdentityFrame RenderIdentityFrame(estimator::BallSet set, std::uint64_t seed, int index,
                                          const IdentityTrainingOptions& options);

// The labelled descriptors of every ball of every frame (pool, snooker, carom, blackball).
std::vector<estimator::IdentitySample> RenderedIdentitySamples(
    const IdentityTrainingOptions& options);

}  // namespace billiard::bench
