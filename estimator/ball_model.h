// A rig's own look of its balls, learnt once from a frame that shows each ball where it is known
// to lie (`billiard learn-balls`), and used instead of the hand-set colours to name the balls of
// that camera's frames (`billiard detect --ball-model`, `estimator_node --ball-model`).
//
// Identity's hand-set colours (identity_parameters.h) are one manufacturer's balls under white
// light: another set's hues, a camera's own colour response and JPEG shift them, and on cameras
// they were not set on they name about half the balls right (issue 45). What a rig changes is
// what one frame of it shows: each class's colour through this camera, and how much of a stripe's
// disc its white caps take at this camera's resolution and blur. So the model is identity's
// parameters fitted by code (identity_fit.h) on the balls of one frame of the rig, their classes
// given: each class shown takes the median colour of its balls' discs as this camera saw them
// (the stripes' and solids' of one colour pooled, as the hand-set table pools them), the split of
// the stripes' and the solids' plain shares its stripe threshold; what the frame cannot fit (a
// threshold with fewer than kMinBallsPerSide balls on a side, a class not shown) stays the
// hand-set's. A frame is named as before (ball_identity.h): every ball's look read after the
// frame's white balance (von Kries 1902, from its cue ball), then the nearest colours, all at once
// with the rack's count of each class. The white balance is what carries the model to another
// light: a light of another colour or strength scales each channel of every ball alike, which the
// cue ball's grey undoes, so the colours learnt under one light are those read under another.
//
// The model is a JSON file (BallModelJson):
//   {"format": "billiard-ball-model", "version": 1, "ball_set": "pool",
//    "learnt": ["cue", "1", ...],                       // the classes the frame showed
//    "shares": {"cue_white": .., "cue_colour": .., "black_share": .., "stripe_plain": ..},
//    "colours": [{"table": "pool", "class": "3", "lab": [L*, a*, b*]}, ...]}
// every colour and share of the parameters written, so that a model names balls the same
// whatever the hand-set values become.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "estimator/identity_parameters.h"

namespace billiard::estimator {

struct BallModel {
  BallSet set = BallSet::kPool;
  IdentityParameters identity;
  std::vector<BallClass> learnt;  // the classes the learning frame showed, each once
};

// A ball of the learning frame: its class and its centre in the frame [px].
struct PlacedBall {
  BallClass ball_class = BallClass::kUnknown;
  Eigen::Vector2d pixel;
};

// The detection each placed ball is: the nearest one whose outline holds its centre, or -1 when
// none does. Throws std::invalid_argument when two placed balls are the same detection (a layout
// whose balls are closer than a ball's radius, or a ball listed twice).
std::vector<int> MatchPlacedBalls(const std::vector<PlacedBall>& placed,
                                  const std::vector<BallDetection>& balls);

// The model of a rig from one frame: `bgr` the frame as the detector searched it
// (BallDetector::SearchedFrame), `balls` every ball found in it (the white balance is read from
// all of them), `placed` the balls whose classes are known, `matched` their detections
// (MatchPlacedBalls; -1 for a ball not found, which is left out).
BallModel LearnBallModel(const cv::Mat& bgr, const std::vector<BallDetection>& balls,
                         const std::vector<PlacedBall>& placed, const std::vector<int>& matched,
                         BallSet set);

// The model as the JSON text above, and back; parsing throws std::invalid_argument with the
// reason (prefixed by `origin`, a file's name) for text that is not such a model.
std::string BallModelJson(const BallModel& model);
BallModel ParseBallModel(const std::string& json_text, const std::string& origin);
// The model in the file at `path`; std::invalid_argument when it cannot be read or parsed.
BallModel LoadBallModel(const std::string& path);

}  // namespace billiard::estimator
