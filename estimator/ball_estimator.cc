#include "estimator/ball_estimator.h"

#include <algorithm>

namespace billiard::estimator {

namespace {

// A track's identity is in doubt below this probability of its likeliest class: two balls that
// met share theirs about evenly (0.5); a few frames of detections name a ball above 0.99.
constexpr double kIdentityInDoubt = 0.9;

// The detector looks for the camera's balls: of their size, and of their set's classes; on the
// camera's table when it is the rig's calibration.
DetectorOptions ForTheBalls(const EstimatorOptions& estimator, const camera::CameraModel& camera,
                            const physics::ModelParameters& params) {
  DetectorOptions options = estimator.detector;
  if (options.ball_radius_px <= 0.0) {
    options.ball_radius_px = ExpectedRadiusPx(camera, params.ball.radius);
  }
  options.ball_set = BallSetOf(params.name);
  if (estimator.table_from_camera) {
    options.calibrated = CalibratedTable{camera, params.table, NoseHeight(params.ball.radius)};
  }
  return options;
}

// The tracker tells apart the classes of the same balls.
TrackerOptions ForTheBalls(TrackerOptions options, const physics::ModelParameters& params) {
  options.ball_set = BallSetOf(params.name);
  return options;
}

// Whether a published track's likeliest class is less likely than kIdentityInDoubt.
bool IdentityInDoubt(const std::vector<TrackedBall>& tracks) {
  return std::any_of(tracks.begin(), tracks.end(), [](const TrackedBall& t) {
    return t.confirmed && t.class_confidence < kIdentityInDoubt;
  });
}

}  // namespace

BallEstimator::BallEstimator(const camera::CameraModel& camera,
                             const physics::ModelParameters& params, EstimatorOptions options)
    : camera_(camera),
      params_(params),
      options_(options),
      detector_(ForTheBalls(options, camera, params)),
      tracker_(params, ForTheBalls(options.tracker, params)) {}

Eigen::Vector2d BallEstimator::ToTable(const Eigen::Vector2d& pixel) const {
  return camera_.Unproject(pixel, params_.ball.radius).head<2>();
}

bool BallEstimator::Process(const cv::Mat& frame, double time, FrameStats* stats) {
  if (frame.empty() || frame.cols != camera_.width || frame.rows != camera_.height ||
      time < last_time_) {
    return false;
  }
  last_time_ = time;
  const double radius_px = options_.detector.ball_radius_px > 0.0
                               ? options_.detector.ball_radius_px
                               : ExpectedRadiusPx(camera_, params_.ball.radius);
  std::vector<Eigen::Vector2d> measured;
  std::vector<ClassEvidence> classes;  // one per measurement
  bool full = frames_++ % options_.full_detect_every == 0 || tracker_.tracks().empty();
  if (!full) {
    std::vector<BallDetection> refined;
    for (const Eigen::Vector2d& predicted : tracker_.Predict(time)) {
      const auto found = detector_.RefineAt(
          frame, camera_.Project({predicted.x(), predicted.y(), params_.ball.radius}), radius_px);
      if (!found) {
        full = true;
        break;
      }
      const Eigen::Vector2d x = ToTable(found->pixel);
      // Two tracks on one ball (a tentative one beside a confirmed one) refine to the same
      // pixel: one measurement, or the copy would seed yet another track.
      bool seen = false;
      for (const Eigen::Vector2d& y : measured) seen = seen || (x - y).norm() < params_.ball.radius;
      if (seen) continue;
      measured.push_back(x);
      refined.push_back(*found);
    }
    // RefineAt answers only at the sure score: a track the first frame doubted is published from
    // here, as from any sure detection. The classes are read where a track's is in doubt (balls
    // that met share their identities, ball_tracker.h), not left to the next full detection.
    if (!full && IdentityInDoubt(tracker_.tracks())) detector_.Identify(frame, &refined);
    for (const BallDetection& d : refined) {
      classes.push_back({d.ball_class, d.class_confidence, d.score});
    }
  }
  if (full) {
    measured.clear();
    classes.clear();
    if (detector_.table() && detector_.OutlineAgreement(frame) < kMovedAgreement) {
      ++views_moved_;
      detector_.LearnTable(frame);
    }
    for (const BallDetection& d : detector_.Detect(frame)) {
      measured.push_back(ToTable(d.pixel));
      classes.push_back({d.ball_class, d.class_confidence, d.score});
    }
  }
  tracker_.Update(time, measured, classes);
  if (stats) *stats = {static_cast<int>(measured.size()), full};
  return true;
}

std::vector<TrackedBall> BallEstimator::Balls() const {
  std::vector<TrackedBall> balls;
  for (const TrackedBall& t : tracker_.tracks()) {
    if (t.confirmed) balls.push_back(t);
  }
  return balls;
}

}  // namespace billiard::estimator
