// A labelled set of camera frames, as the detection benchmark reads it: a directory with
// labels.json (as ../shared/data/real-tables/dev/) and its images, and optionally a corners file
// that labels each frame's playing surface.
//
// labels.json: {"FILE": {"balls": [[u, v], ...], "ball_radius_px": R, "in_pocket": [[u, v]...],
// "ignore": [[u, v]...], "view": "overhead"|"oblique", "source": "...", ...}, "_...": notes}.
// `balls` must be found; `in_pocket` and `ignore` (balls in pockets, in hand, mostly hidden)
// count neither way; `view`, when given, files the frame under that view, else under the view the
// table finder sees.
//
// Optional, per frame: `classes` (parallel to `balls`: "cue", "1".."15", "solid", "stripe",
// "eight", snooker's colours, carom's "white", "yellow", "red"; null where it cannot be told) and
// `kind` ("pool", "snooker", "carom"), which choose the ball set and score identity; and, from a
// corners file (LoadTableCorners), the playing surface's four corners, which score the table.
#pragma once

#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "estimator/ball_class.h"

namespace billiard::bench {

struct LabelledFrame {
  std::string file;                      // relative to the set's directory
  std::vector<Eigen::Vector2d> balls;    // must be found [px]
  std::vector<Eigen::Vector2d> ignored;  // in a pocket, in hand, hidden [px]
  double radius_px = 0;                  // typical ball radius [px]
  std::string view;                      // "overhead", "oblique" or "" (not labelled)
  std::string source;
  std::vector<std::string> classes;  // per ball, "" where not labelled
  std::string kind;                  // "pool", "snooker", "carom" or "" (not labelled)
  // The playing surface's corners in order around the table, and the side (corner k to k + 1)
  // that is out of the frame (-1: none).
  std::optional<std::array<Eigen::Vector2d, 4>> corners;
  int unseen_side = -1;
  cv::Mat image;  // the frame, when not read from `file`
};

// The frames of a labelled set, in the order of labels.json. Throws std::invalid_argument with a
// one-line reason naming the file and the entry when labels.json is missing or malformed.
std::vector<LabelledFrame> LoadLabelledSet(const std::string& directory);

// Adds the corner labels of `path` ({"FILE": {"corners": [[u, v] x 4], "unseen_side": k}, "_...":
// notes}) to the frames they name; frames it does not name keep none. Throws
// std::invalid_argument with a one-line reason when the file is missing or malformed.
void LoadTableCorners(const std::string& path, std::vector<LabelledFrame>* frames);

// The detector's ball set for a frame's `kind` and labelled classes: carom and snooker by kind;
// pool by kind, unless its balls are labelled by colour (English pool's reds and yellows: the
// blackball set).
estimator::BallSet BallSetFor(const LabelledFrame& frame);

// Whether a detection's class is a labelled class: the same name, a number of that group for
// "solid" (1-7), "stripe" (9-15) and "eight", "cue" for carom's "white".
bool ClassMatches(const std::string& label, estimator::BallClass detected);

}  // namespace billiard::bench
