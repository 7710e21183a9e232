#include "estimator/node/estimator_node.h"

#include <algorithm>
#include <exception>
#include <iostream>
#include <utility>

#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "sim/params/parameter_sets.h"

namespace billiard::estimator_node {

// The estimator's classes are the message's.
static_assert(static_cast<int>(estimator::BallClass::kUnknown) == ball_state_t::CLASS_UNKNOWN &&
              static_cast<int>(estimator::BallClass::kCue) == ball_state_t::CLASS_CUE &&
              static_cast<int>(estimator::BallClass::kRed) == ball_state_t::CLASS_RED &&
              static_cast<int>(estimator::BallClass::kBlack) == ball_state_t::CLASS_BLACK);

table_state_t TableStateMessage(const std::vector<estimator::TrackedBall>& balls,
                                std::int64_t utime, double ball_radius) {
  table_state_t m{};
  m.utime = utime;
  for (const estimator::TrackedBall& b : balls) {
    ball_state_t s{};
    s.utime = utime;
    s.ball_id = b.id;
    s.ball_class = static_cast<int8_t>(b.ball_class);
    s.class_confidence = static_cast<float>(b.class_confidence);
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

EstimatorNode::EstimatorNode(lcm::LCM& lcm, const camera::CameraModel& camera,
                             const physics::ModelParameters& params,
                             estimator::EstimatorOptions options, messages::DecodeLimits limits,
                             Log log)
    : lcm_(lcm),
      params_(params),
      options_(options),
      estimator_(camera, params, options),
      limits_(limits),
      log_(log ? std::move(log) : Log([](const std::string& line) {
        std::cerr << "estimator_node: " << line << std::endl;
      })),
      health_("estimator_node", log_) {
  health_.SetParameters(params::ParameterSetLabel(params_), params::ParameterHash(params_));
  subscription_ = lcm_.subscribe(messages::kCameraImageChannel, &EstimatorNode::OnImage, this);
}

EstimatorNode::~EstimatorNode() {
  if (subscription_) lcm_.unsubscribe(subscription_);
}

bool EstimatorNode::Work() {
  health_.PublishIfDue(lcm_);
  return false;
}

void EstimatorNode::OnImage(const lcm::ReceiveBuffer* rbuf, const std::string&) {
  const auto arrived = nodes::NodeHealth::Clock::now();
  try {
    health_.Received();
    image_t message;
    if (std::string why = messages::DecodeChecked(rbuf->data, rbuf->data_size, message);
        !why.empty()) {
      return Drop(why);
    }
    switch (clock_.Accept(message.utime)) {
      case nodes::MessageClock::Verdict::kNext:
        break;
      case nodes::MessageClock::Verdict::kDuplicate:
        return health_.Count("duplicate");
      case nodes::MessageClock::Verdict::kLate:
        return Drop("a frame at utime " + std::to_string(message.utime) + " after one at " +
                    std::to_string(clock_.latest()) + " (late or reordered)");
      case nodes::MessageClock::Verdict::kNewClock:
        health_.Count("clock_reset");
        log_(std::string(messages::kCameraImageChannel) + ": a new clock at utime " +
             std::to_string(message.utime) + ": tracking starts again");
        estimator_ = estimator::BallEstimator(estimator_.camera(), params_, options_);
        break;
    }
    const messages::DecodedImage image = messages::DecodeImage(message, limits_);
    if (!image.ok) return Drop(image.error);
    if (!estimator_.Process(image.image, 1e-6 * static_cast<double>(message.utime))) {
      const camera::CameraModel& c = estimator_.camera();
      return Drop("a " + std::to_string(image.image.cols) + "x" + std::to_string(image.image.rows) +
                  " frame, but the camera is " + std::to_string(c.width) + "x" +
                  std::to_string(c.height));
    }
    ++frames_;
    if (estimator_.views_moved() != views_moved_) {
      views_moved_ = estimator_.views_moved();
      health_.Set("view_moved", views_moved_);
      log_("estimator_node: the camera's view has moved (the table learnt again); its "
           "calibration is of the old view");
    }
    std::vector<estimator::TrackedBall> balls = estimator_.Balls();
    if (balls.size() > static_cast<std::size_t>(messages::kMaxBalls)) {
      // More than a table holds (clutter taken for balls): the best-known ones go out, since a
      // state over the limit would be refused whole by every receiver.
      health_.Count("balls_not_published", balls.size() - messages::kMaxBalls);
      std::partial_sort(balls.begin(), balls.begin() + messages::kMaxBalls, balls.end(),
                        [](const estimator::TrackedBall& a, const estimator::TrackedBall& b) {
                          return a.covariance.trace() < b.covariance.trace();
                        });
      balls.resize(messages::kMaxBalls);
    }
    const table_state_t state = TableStateMessage(balls, message.utime, params_.ball.radius);
    if (lcm_.publish(messages::kTableStateChannel, &state) != 0)
      return Drop("publishing TABLE_STATE failed");
    health_.Published();
    health_.Latency(nodes::NodeHealth::Clock::now() - arrived);
  } catch (const std::exception& e) {
    Drop(e.what());
  } catch (...) {
    Drop("unknown exception");
  }
}

}  // namespace billiard::estimator_node
