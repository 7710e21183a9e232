// The estimator node: every CAMERA_IMAGE frame through the estimator (ball_estimator.h), and the
// tracked balls out as TABLE_STATE.
//
//   CAMERA_IMAGE  image_t        decoded and checked (image_codec.h); a frame that does not
//                                decode, is empty, oversized, of another size than the camera's,
//                                or older than the last one is logged and dropped
//   TABLE_STATE   table_state_t  the confirmed balls, utime of the frame, ball_id of the track
//
// The state depends only on the frames received, never on the clock, so a logged run replays to
// the same TABLE_STATE messages. A node never dies on a message: handlers catch what they throw.
#pragma once

#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <string>

#include "ball_estimator.h"
#include "billiard/table_state_t.hpp"
#include "image_codec.h"

namespace billiard::estimator {

inline constexpr char kCameraImageChannel[] = "CAMERA_IMAGE";
inline constexpr char kTableStateChannel[] = "TABLE_STATE";

// The table state message of the estimator's confirmed balls at `utime`.
table_state_t TableStateMessage(const std::vector<TrackedBall>& balls, std::int64_t utime,
                                double ball_radius);

class EstimatorNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  // Subscribes on `lcm`, which must outlive the node; `log` gets one line per dropped frame
  // (stderr by default).
  EstimatorNode(lcm::LCM& lcm, const CameraModel& camera, const ModelParameters& params,
                EstimatorOptions options = {}, DecodeLimits limits = {}, Log log = nullptr);
  ~EstimatorNode();
  EstimatorNode(const EstimatorNode&) = delete;
  EstimatorNode& operator=(const EstimatorNode&) = delete;

  long frames() const { return frames_; }
  long dropped() const { return dropped_; }

 private:
  void OnImage(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void Drop(const std::string& why);

  lcm::LCM& lcm_;
  BallEstimator estimator_;
  double ball_radius_;
  DecodeLimits limits_;
  Log log_;
  lcm::Subscription* subscription_ = nullptr;
  long frames_ = 0, dropped_ = 0;
};

}  // namespace billiard::estimator
