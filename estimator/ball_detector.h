// Balls in a camera frame of the table: where they are to a fraction of a pixel, and how sure.
//
// Nothing is tuned to one table, camera or light. Each camera's first frame teaches the detector
// its table (LearnTable):
//   - The table (table_finder.h): the cloth of any colour, its four sides, the perspective they
//     imply. Only what lies on the table is looked at: nothing on the floor, the rails, the
//     players or a broadcaster's graphics.
//   - The local colour of the cloth (ClothModel), which vignetting and mixed lights change across
//     the table.
//   - The balls' scale (ball_scale.h): how large a ball looks at each place. Given as
//     DetectorOptions::ball_radius_px (by a calibrated camera) or measured: the compact blobs of
//     not-cloth on the table are outlined (ball_outline.h) and the radius most of them agree on,
//     relative to the table's depth at each, is the scale; without such blobs (an empty table, a
//     rack), the table's size gives a first one. A measured scale is settled on the first frame
//     with balls, from the balls found.
//
// Then every frame (Detect):
//   1. Every edge on the table votes for the centres of the ball-sized circles it could lie on
//      (circle_votes.h): one peak per ball, isolated, in a rack, against a cushion or half hidden.
//   2. Each peak's outline is fitted at full resolution (ball_outline.h).
//   3. Each outline is scored (0..1) by what makes it a ball rather than a shadow, a pocket, a
//      hand or a spot on the cloth: enough of its circle has an edge and voted for it, its radius
//      is the ball's at that place, and inside it is not the cloth (its colour is far from the
//      cloth's) or it shines (a ball is glossy: its highlight stands out of its own colour, which
//      also tells a dark ball from a shadow). An outline scored below sure is voted for again at
//      full resolution (the black in the middle of a rack loses its creases at the votes' own).
//   4. Best first, an outline is kept unless it overlaps one kept already (balls touch but never
//      overlap): a shadow beside its ball, a second outline of one ball.
//   5. Each ball kept is identified by its colours (ball_identity.h).
//
// RefineAt is the tracker's: the ball near a predicted pixel, outlined and scored the same way.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "estimator/ball_class.h"
#include "estimator/ball_scale.h"
#include "estimator/cloth_model.h"
#include "estimator/identity_parameters.h"
#include "estimator/table_fallback.h"
#include "estimator/table_finder.h"
#include "estimator/table_outline.h"
#include "sim/camera/camera_model.h"

namespace billiard::estimator {

struct BallDetection {
  Eigen::Vector2d pixel;  // centre (u, v) [px], sub-pixel, OpenCV convention (pixel centres at
                          // integers)
  double radius_px = 0;   // fitted radius of the ball's outline [px]
  double score = 0;       // 0..1: how ball-like (outline, radius, colour, shine)
  // Which ball it is (ball_identity.h), and how sure: set by Detect, unknown from RefineAt.
  BallClass ball_class = BallClass::kUnknown;
  double class_confidence = 0;
};

struct DetectorOptions {
  // Expected ball radius [px] at the centre of the table (elsewhere the table's perspective
  // scales it); 0 = measure it from the balls in the frame.
  double ball_radius_px = 0;
  // Detections scoring below this are not reported (`billiard bench-detect --cross-validate`
  // fits it on labelled frames).
  double min_score = 0.5;
  // The balls' set, for their classes, and the colours and shares they are told apart by.
  BallSet ball_set = BallSet::kPool;
  IdentityParameters identity = HandSetIdentity();
  // A calibrated camera and its table: the table is where the camera puts it, never looked for
  // (table_fallback.h).
  std::optional<CalibratedTable> calibrated;
  // The ball's radius over the playing surface's width, for a first scale where nothing on the
  // table is the size and shape of a ball (an empty table, a rack): pool balls on a 9-ft table.
  double ball_to_table_width = 0.028575 / 1.27;
};

// The expected radius [px] of a ball of radius `ball_radius` [m] at the image centre.
double ExpectedRadiusPx(const camera::CameraModel& camera, double ball_radius);

class BallDetector {
 public:
  // The first detector of a process also builds OpenCV's L*a*b* tables (PrepareLabConversion).
  explicit BallDetector(DetectorOptions options = {});

  // Learns the table, its cloth and the balls' scale from a BGR (CV_8UC3) or grey (CV_8UC1)
  // frame: the calibrated camera's table (DetectorOptions::calibrated), else the table found in
  // the frame. False, failure() saying why, when no table is found; then a table learnt before
  // from a frame of this size is kept (an arm across a side, a player leaning over the table:
  // the rig has not moved), else the cloth alone is the region looked at (table_fallback.h's
  // ClothOnly; none when no cloth is found either). The table and its lights do not change
  // between frames, so this runs once, on Detect's first frame (and again when the frame size
  // changes, while only the cloth is known, or when asked).
  bool LearnTable(const cv::Mat& image);

  // Every ball in a frame, best score first, identified. Where no table is found, the balls on
  // the cloth (table()->origin kClothOnly; failure() says why no table); empty when no cloth is
  // found either or no ball is there.
  std::vector<BallDetection> Detect(const cv::Mat& image);

  // The ball near `predicted` (within about one radius of `radius_px`), for a tracker. Before a
  // table is learnt, the cloth is the colour around the window. Empty when nothing there is
  // surely a ball (a score of 0.8, where Detect takes 0.5): where a prediction has overshot a
  // ball that was stopped or turned (by a collision, a cushion, a pocket's jaw), the outline
  // found beside it is a part of the ball's, of its shadow or of a cushion's edge, scoring
  // 0.2-0.75, and the tracker needs a full Detect to find the ball.
  std::optional<BallDetection> RefineAt(const cv::Mat& image, const Eigen::Vector2d& predicted,
                                        double radius_px) const;

  // Names the balls of a frame as Detect names its own (ball_identity.h): every ball of the frame
  // at once, the rack's count of each class respected. For balls RefineAt found.
  void Identify(const cv::Mat& image, std::vector<BallDetection>* balls) const;

  // The frame as Detect looks for and names the balls in it: BGR, smoothed when the camera the
  // table was learnt from is noisy. ball_identity.h's NameBalls of LookAtBalls of it, with
  // options().ball_set, is Detect's naming under any identity parameters.
  cv::Mat SearchedFrame(const cv::Mat& image) const;

  // How much of the table's outline a frame shows where the frame the table was learnt from
  // showed it: the normalized correlation of the two frames' colour gradients along the cloth's
  // outline (the rails and pockets, which do not move when the balls do), at the table search's
  // resolution; 1 for the same view, about 0 when the camera has moved by more than the outline's
  // width. 1 before a table is learnt, or for a frame of another size.
  double OutlineAgreement(const cv::Mat& image) const;

  const DetectorOptions& options() const { return options_; }
  // The region the balls are looked for in: the table, or the cloth alone (its origin says).
  const std::optional<TableRegion>& table() const { return table_; }
  // Whether the table is known (found or calibrated), not the cloth alone.
  bool knows_table() const { return table_ && table_->origin != TableOrigin::kClothOnly; }
  const std::optional<BallScale>& scale() const { return scale_; }
  const ClothModel& cloth() const { return cloth_; }
  // The ball radius at the table's centre [px] (the option, or the measure); 0 before one is
  // learnt.
  double radius_px() const { return scale_ ? scale_->radius_at_centre : 0.0; }
  // Why the last LearnTable found no table; empty when it found one or had a calibration.
  const std::string& failure() const { return failure_; }

 private:
  // Whether FindBalls votes again, at full resolution, for the outlines it doubts.
  enum class Doubts { kAsVoted, kVotedAgain };
  // Step 5 on a frame as Detect smooths it.
  void Name(const cv::Mat& bgr, std::vector<BallDetection>* balls) const;
  // Steps 1 to 4 (see the top of the file) at the current scale.
  std::vector<BallDetection> FindBalls(const cv::Mat& bgr, Doubts doubts) const;
  // Settles a measured scale from the balls found, finding them again if it changed.
  void SettleScale(const cv::Mat& bgr, std::vector<BallDetection>* balls);
  // A larger scale than the measured one, where it makes clearly more balls sure (the top of
  // ball_detector.cc), with the balls found at it.
  void TryLargerScales(const cv::Mat& bgr, std::vector<BallDetection>* balls);
  // The least scale the table allows its balls (ball_scale.h) where it is whole in the frame or
  // completed across the frame's border (table_partial.h: its width seen, or its length); 0 where
  // the frame cuts it otherwise (a cut table read as whole is smaller than it is) or only the
  // cloth is known (no table).
  double LeastPlausibleScale() const;
  // The calibrated camera's table, the table found, or the cloth alone; failure_ says why no
  // table was found.
  std::optional<TableRegion> LookForTable(const cv::Mat& bgr);
  // The frame as the balls are looked for in it: smoothed a little if the camera is noisy.
  cv::Mat Smoothed(const cv::Mat& bgr) const;

  DetectorOptions options_;
  std::optional<TableRegion> table_;
  std::optional<BallScale> scale_;
  bool scale_settled_ = false;
  ClothModel cloth_;  // of the frame as searched
  double unsmoothed_edge_noise_ = 0;
  double smoothing_px_ = 0;
  cv::Size frame_size_;
  std::string failure_;
  TableOutline outline_;  // of the frame the table was learnt from (OutlineAgreement)
};

}  // namespace billiard::estimator
