// Detections scored against one labelled frame: which detection matches which label (within
// max(8 px, 0.6 R), one to one, nearest pairs first; balls labelled in a pocket or ignored count
// neither way), why each label was missed and what each false detection was, and how far the
// table found is from the labelled playing surface.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "bench/labelled_set.h"
#include "estimator/ball_detector.h"

namespace billiard::bench {

// A table is found when every labelled side of the playing surface found is within this of the
// labelled one at both of its ends (in the frame).
inline constexpr double kTableSideTolerancePx = 2.0;

// How far a detection may be from its label [px].
double MatchDistancePx(double radius_px);

struct FrameScore {
  std::string file, view, table_view, source;
  std::string failure;  // why the detector found no table or no balls' scale, else ""
  int labels = 0, found = 0, false_detections = 0;
  std::vector<double> centre_errors;  // [px], of the matched labels
  cv::Size size;
  // On one core: the first frame (the table, the cloth and the scale learnt, then the balls) and
  // a next frame of the same camera (the balls only; the median of a few), wall time [ms].
  double first_frame_ms = 0, next_frame_ms = 0;
  std::vector<Eigen::Vector2d> missed;  // labels no detection matched
  std::vector<estimator::BallDetection> detections;
  std::vector<bool> detection_matched;  // per detection: a label's (or an ignored ball's)
  std::vector<int> detection_label;     // per detection: the label it matched, or -1
  std::optional<estimator::TableRegion> table;
  // Against the corner labels: the largest distance [px] of a found side from its labelled side
  // at the labelled side's ends in the frame (-1: no labels, or no table found).
  double table_side_error_px = -1;
  bool table_labelled = false;
  // Identity: matched balls whose class is labelled, and of those, named right.
  int classed = 0, classed_right = 0;
  // Why each label was missed and what each false detection was (MissCause, FalseCause).
  std::vector<std::string> missed_causes, false_causes;
};

// The largest distance [px] of a found side from its labelled one at the labelled side's ends in
// the frame of `size` (the side out of the frame and the parts beyond its edges not counted), the
// found corners matched to the labelled ones by the turn and direction around the table that puts
// them nearest. The frame must have corner labels.
double TableSideError(const LabelledFrame& frame, const estimator::TableRegion& table,
                      const cv::Size& size);

// Why a label was missed: "no table" (none found), "outside the table found" (beyond the playing
// surface found), "by the cushion" (its centre within 1.5 R of a labelled side), "in a cluster"
// (within 2.5 R of another ball), else "on open cloth".
// What a false detection was: "duplicate" (within 2 R of a label another detection matched),
// "off the table" (outside the labelled playing surface), else "on the table" (a hand, a cue, a
// pocket, a mark).
void ExplainMisses(const LabelledFrame& frame, FrameScore* score);

// Detections scored against a frame's labels.
FrameScore ScoreFrame(const LabelledFrame& frame,
                      const std::vector<estimator::BallDetection>& detections);

}  // namespace billiard::bench
