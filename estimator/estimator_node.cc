#include "estimator_node.h"

#include <exception>
#include <iostream>
#include <utility>

namespace billiard::estimator {

table_state_t TableStateMessage(const std::vector<TrackedBall>& balls, std::int64_t utime,
                                double ball_radius) {
  table_state_t m{};
  m.utime = utime;
  for (const TrackedBall& b : balls) {
    ball_state_t s{};
    s.utime = utime;
    s.ball_id = b.id;
    const Eigen::Matrix<double, 7, 1> x = b.BallState(ball_radius);
    const Eigen::Matrix<double, 7, 7, Eigen::RowMajor> c = b.BallCovariance(ball_radius);
    for (int i = 0; i < 2; ++i) s.position[i] = x[i];
    for (int i = 0; i < 2; ++i) s.velocity[i] = x[2 + i];
    for (int i = 0; i < 3; ++i) s.spin[i] = x[4 + i];
    std::copy(c.data(), c.data() + 49, s.covariance);
    m.balls.push_back(s);
  }
  m.num_balls = static_cast<int32_t>(m.balls.size());
  return m;
}

EstimatorNode::EstimatorNode(lcm::LCM& lcm, const CameraModel& camera,
                             const ModelParameters& params, EstimatorOptions options,
                             DecodeLimits limits, Log log)
    : lcm_(lcm),
      estimator_(camera, params, options),
      ball_radius_(params.ball.radius),
      limits_(limits),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "estimator_node: " << line << std::endl;
      })) {
  subscription_ = lcm_.subscribe(kCameraImageChannel, &EstimatorNode::OnImage, this);
}

EstimatorNode::~EstimatorNode() {
  if (subscription_) lcm_.unsubscribe(subscription_);
}

void EstimatorNode::Drop(const std::string& why) {
  ++dropped_;
  try {
    log_(std::string(kCameraImageChannel) + ": dropped a frame: " + why);
  } catch (...) {
  }
}

void EstimatorNode::OnImage(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  try {
    image_t message;
    if (message.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) !=
        static_cast<int>(rbuf->data_size)) {
      return Drop(std::to_string(rbuf->data_size) + " bytes that do not decode as image_t");
    }
    const DecodedImage image = DecodeImage(message, limits_);
    if (!image.ok) return Drop(image.error);
    if (!estimator_.Process(image.image, 1e-6 * static_cast<double>(message.utime))) {
      const CameraModel& c = estimator_.camera();
      return Drop("a " + std::to_string(image.image.cols) + "x" + std::to_string(image.image.rows) +
                  " frame at utime " + std::to_string(message.utime) + " (the camera is " +
                  std::to_string(c.width) + "x" + std::to_string(c.height) +
                  ", and time may not go back)");
    }
    ++frames_;
    const table_state_t state = TableStateMessage(estimator_.Balls(), message.utime, ball_radius_);
    if (lcm_.publish(kTableStateChannel, &state) != 0) Drop("publishing TABLE_STATE failed");
  } catch (const std::exception& e) {
    Drop(e.what());
  } catch (...) {
    Drop("unknown exception");
  }
}

}  // namespace billiard::estimator
