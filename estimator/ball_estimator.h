// From camera frames to ball states: detection (ball_detector.h), the camera model back to the
// table at the height of the ball's centre, and tracking (ball_tracker.h).
//
// Speed: a full-frame Detect costs several times a RefineAt per ball, so once every ball is
// tracked each frame only refines the balls near their predicted pixels, and a full Detect runs
// every `full_detect_every` frames (to pick up a ball put on the table) or when a refinement
// misses. The refined balls' classes are read (BallDetector::Identify) on the frames where a
// published track's identity is in doubt, as after two balls met and shared theirs
// (ball_tracker.h): the next full detection may be a second away.
//
// A fixed camera's table is learnt once, on its first frame (or given by its calibration:
// EstimatorOptions::table_from_camera), and kept. Each full detection first
// checks that the view has not moved (BallDetector::OutlineAgreement below kMovedAgreement: the
// rails and pockets are no longer where they were); if it has, the table is learnt again from
// that frame and the move counted (views_moved()): the camera model, calibrated for the old view,
// is then stale, which the node says in NODE_STATUS. A frame whose table is not found keeps the
// one learnt before; before any is, the balls on the cloth are still found
// (BallDetector::LearnTable).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "estimator/ball_detector.h"
#include "estimator/ball_tracker.h"
#include "sim/camera/camera_model.h"
#include "sim/physics/parameters.h"

namespace billiard::estimator {

// The outline agreement under which the view has moved (about 0.9 and more for a still camera
// with balls and players moving; a few pixels of a move at the search resolution drop it below
// 0.3).
inline constexpr double kMovedAgreement = 0.5;

struct EstimatorOptions {
  DetectorOptions detector;
  // Whether the camera is this rig's calibration (`billiard calibrate`): its table is the one the
  // balls are looked for on, never looked for itself (table_fallback.h), so that a frame with an
  // arm across the table is read like any other. Otherwise the table is found on the first frame
  // (and kept where a later frame's is not found).
  bool table_from_camera = false;
  TrackerOptions tracker;
  int full_detect_every = 30;  // frames
};

struct FrameStats {
  int detections = 0;
  bool full_detect = false;
};

class BallEstimator {
 public:
  // The detector's expected radius comes from the camera and the ball unless set in options.
  BallEstimator(const camera::CameraModel& camera, const physics::ModelParameters& params,
                EstimatorOptions options = {});

  // Processes the frame exposed at `time` [s]. Returns false, changing nothing, for an empty
  // frame, a frame of another size than the camera's, or a time that goes back.
  bool Process(const cv::Mat& frame, double time, FrameStats* stats = nullptr);

  // The confirmed tracks: what is published.
  std::vector<TrackedBall> Balls() const;

  const camera::CameraModel& camera() const { return camera_; }
  // How many times the view has moved since the first frame (see the top of the file).
  int views_moved() const { return views_moved_; }

 private:
  Eigen::Vector2d ToTable(const Eigen::Vector2d& pixel) const;

  camera::CameraModel camera_;
  physics::ModelParameters params_;
  EstimatorOptions options_;
  BallDetector detector_;
  BallTracker tracker_;
  long frames_ = 0;
  double last_time_ = -1e300;
  int views_moved_ = 0;
};

}  // namespace billiard::estimator
