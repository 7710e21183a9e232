// The estimator node: every CAMERA_IMAGE frame through the estimator (ball_estimator.h), and the
// tracked balls out as TABLE_STATE.
//
//   CAMERA_IMAGE  image_t        decoded and checked (message_checks.h, image_codec.h); a frame
//                                that does not decode (a corrupt or truncated JPEG among them),
//                                is empty, oversized, of another size than the camera's, or older
//                                than the last one (late or reordered) is logged and dropped; the
//                                same frame again is counted and ignored
//   TABLE_STATE   table_state_t  the confirmed balls, utime of the frame, ball_id of the track
//   NODE_STATUS   node_status_t  once a second (node_health.h), from Work(); its counter
//                                view_moved says how often the camera's view has moved
//                                (ball_estimator.h), logged once a move
//
// Frames that show a new clock (message_clock.h: a camera or simulator that restarted) drop the
// tracks of the old clock, and tracking starts again.
//
// The state depends only on the frames received, never on the clock, so a logged run replays to
// the same TABLE_STATE messages. A node never dies on a message: handlers catch what they throw.
#pragma once

#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <string>

#include "estimator/ball_estimator.h"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/image_codec.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/message_clock.h"
#include "lcmtypes/node/node_health.h"

namespace billiard::estimator_node {

// The table state message of the estimator's confirmed balls at `utime`.
table_state_t TableStateMessage(const std::vector<estimator::TrackedBall>& balls,
                                std::int64_t utime, double ball_radius);

class EstimatorNode {
 public:
  using Log = std::function<void(const std::string& line)>;

  // Subscribes on `lcm`, which must outlive the node; `log` gets one line per dropped frame
  // (stderr by default).
  EstimatorNode(lcm::LCM& lcm, const camera::CameraModel& camera,
                const physics::ModelParameters& params, estimator::EstimatorOptions options = {},
                messages::DecodeLimits limits = {}, Log log = nullptr);

  ~EstimatorNode();
  EstimatorNode(const EstimatorNode&) = delete;
  EstimatorNode& operator=(const EstimatorNode&) = delete;

  // Publishes NODE_STATUS when due; the frames themselves are processed as they arrive. Returns
  // false: no work waits (node_loop.h).
  bool Work();

  long frames() const { return frames_; }
  // The node's counters; TakeStatus() on it starts a new latency period.
  nodes::NodeHealth& health() { return health_; }

 private:
  void OnImage(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void Drop(const std::string& why) {
    health_.Dropped(std::string(messages::kCameraImageChannel) + ": " + why);
  }

  lcm::LCM& lcm_;
  const physics::ModelParameters params_;
  const estimator::EstimatorOptions options_;
  estimator::BallEstimator estimator_;
  messages::DecodeLimits limits_;
  Log log_;
  nodes::NodeHealth health_;
  lcm::Subscription* subscription_ = nullptr;
  long frames_ = 0;
  int views_moved_ = 0;
  nodes::MessageClock clock_;
};

}  // namespace billiard::estimator_node
