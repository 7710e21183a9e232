// The estimator node in-process over memq://: rendered frames in every encoding become
// TABLE_STATE; bad frames are dropped with a reason and the node goes on; a ball model of other
// balls stops its command line.
#include "estimator/node/estimator_node.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "estimator/ball_model.h"
#include "estimator/node/estimator_node_command.h"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/testing/damaged_jpeg.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator_node {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

class EstimatorNodeTest : public ::testing::Test {
 protected:
  EstimatorNodeTest()
      : camera_(camera::CameraModel::Overhead(Pool().table, 640, 360)),
        renderer_(camera_, Pool()),
        node_(lcm_, camera_, Pool(), {}, {},
              [this](const std::string& line) { log_.push_back(line); }) {
    lcm_.subscribe(messages::kTableStateChannel, &EstimatorNodeTest::OnState, this);
    for (int i : {0, 3, 8}) {
      balls_.push_back(
          render::RenderBall::AtRest(i, render::PoolBallColour(i), truth_[balls_.size()]));
    }
  }

  void OnState(const lcm::ReceiveBuffer*, const std::string&, const table_state_t* m) {
    states_.push_back(*m);
  }

  // Publishes `message` and handles until the node has dealt with it.
  void Send(const image_t& message) {
    lcm_.publish(messages::kCameraImageChannel, &message);
    while (lcm_.handleTimeout(0) > 0) {
    }
  }

  image_t Frame(std::int64_t utime, messages::ImageEncoding encoding) {
    return messages::EncodeImage(renderer_.Render(balls_, 1e-6 * utime), utime, encoding);
  }

  lcm::LCM lcm_{"memq://"};
  camera::CameraModel camera_;
  render::TableRenderer renderer_;
  std::vector<std::string> log_;
  EstimatorNode node_;
  std::vector<Eigen::Vector2d> truth_ = {{0.5, 0.4}, {1.3, 0.9}, {2.0, 0.3}};
  std::vector<render::RenderBall> balls_;
  std::vector<table_state_t> states_;
};

TEST_F(EstimatorNodeTest, FramesInEveryEncodingBecomeTableStates) {
  const messages::ImageEncoding encodings[] = {messages::ImageEncoding::kRgb,
                                               messages::ImageEncoding::kGray,
                                               messages::ImageEncoding::kMjpeg};
  for (int f = 0; f < 12; ++f) Send(Frame(1'000'000 + 8'333 * f, encodings[f % 3]));
  ASSERT_EQ(states_.size(), 12u);
  EXPECT_EQ(node_.health().dropped(), 0) << (log_.empty() ? "" : log_[0]);
  const table_state_t& last = states_.back();
  EXPECT_EQ(last.utime, 1'000'000 + 8'333 * 11);
  ASSERT_EQ(last.num_balls, 3);
  for (const Eigen::Vector2d& x : truth_) {
    double nearest = 1e9;
    for (const ball_state_t& b : last.balls) {
      nearest = std::min(nearest, std::hypot(b.position[0] - x.x(), b.position[1] - x.y()));
      EXPECT_EQ(b.utime, last.utime);
      EXPECT_GT(b.covariance[0], 0.0);
    }
    // 640 px over 2.54 m: 4.3 mm per pixel.
    EXPECT_LT(nearest, 2e-3) << x.transpose();
  }
}

TEST_F(EstimatorNodeTest, BadFramesAreDroppedWithAReasonAndTheNodeGoesOn) {
  Send(Frame(2'000'000, messages::ImageEncoding::kRgb));
  const std::uint8_t garbage[] = {1, 2, 3, 4, 5};
  lcm_.publish(messages::kCameraImageChannel, garbage, sizeof garbage);
  while (lcm_.handleTimeout(0) > 0) {
  }
  image_t empty = Frame(2'100'000, messages::ImageEncoding::kRgb);
  empty.data.clear();
  empty.size = 0;
  Send(empty);
  image_t huge = Frame(2'200'000, messages::ImageEncoding::kGray);
  huge.width = 100000;
  Send(huge);
  Send(messages::EncodeImage(cv::Mat(100, 100, CV_8UC3, cv::Scalar(0, 0, 0)), 2'300'000,
                             messages::ImageEncoding::kRgb));  // not the camera's size
  Send(Frame(1'000'000, messages::ImageEncoding::kRgb));       // older than the last frame
  EXPECT_EQ(node_.health().dropped(), 5);
  ASSERT_EQ(log_.size(), 5u);
  for (const std::string& line : log_) {
    EXPECT_EQ(line.rfind("dropped: CAMERA_IMAGE: ", 0), 0u) << line;
  }
  EXPECT_NE(log_.back().find("late or reordered"), std::string::npos) << log_.back();
  Send(Frame(2'400'000, messages::ImageEncoding::kMjpeg));
  Send(Frame(2'400'000,
             messages::ImageEncoding::kMjpeg));  // the same frame again: not a second state
  EXPECT_EQ(node_.frames(), 2);
  EXPECT_EQ(states_.size(), 2u);
  EXPECT_EQ(node_.health().counter("duplicate"), 1);
  EXPECT_EQ(node_.health().dropped(), 5);
}

TEST_F(EstimatorNodeTest, CorruptAndTruncatedJpegFramesAreDroppedAndCounted) {
  using messages::testing::WithData;
  Send(Frame(3'000'000, messages::ImageEncoding::kMjpeg));
  ASSERT_EQ(states_.size(), 1u);
  const image_t corrupt = Frame(3'008'333, messages::ImageEncoding::kMjpeg);
  Send(WithData(corrupt, messages::testing::WithStrayMarker(corrupt.data, 0.5)));
  const image_t closed = Frame(3'016'667, messages::ImageEncoding::kMjpeg);
  Send(WithData(closed, messages::testing::CutAndClosed(closed.data, 0.5)));
  const image_t truncated = Frame(3'025'000, messages::ImageEncoding::kMjpeg);
  Send(WithData(truncated, messages::testing::Truncated(truncated.data, truncated.size / 2)));
  EXPECT_EQ(states_.size(), 1u) << "no TABLE_STATE for a damaged frame";
  EXPECT_EQ(node_.frames(), 1);
  EXPECT_EQ(node_.health().dropped(), 3);
  ASSERT_EQ(log_.size(), 3u);
  for (const std::string& line : log_) {
    EXPECT_EQ(line.rfind("dropped: CAMERA_IMAGE: ", 0), 0u) << line;
  }
  EXPECT_NE(log_[0].find("Corrupt JPEG data"), std::string::npos) << log_[0];
  EXPECT_NE(log_[1].find("Corrupt JPEG data"), std::string::npos) << log_[1];
  EXPECT_NE(log_[2].find("truncated"), std::string::npos) << log_[2];
  // The next good frame is tracked as before.
  Send(Frame(3'033'333, messages::ImageEncoding::kMjpeg));
  ASSERT_EQ(states_.size(), 2u);
  EXPECT_EQ(states_.back().utime, 3'033'333);
  EXPECT_EQ(node_.health().dropped(), 3);
}

TEST_F(EstimatorNodeTest, ACameraThatRestartsItsClockIsTrackedAfresh) {
  for (int f = 0; f < 6; ++f) Send(Frame(20'000'000 + 8'333 * f, messages::ImageEncoding::kRgb));
  ASSERT_EQ(states_.size(), 6u);
  ASSERT_EQ(states_.back().num_balls, 3);
  Send(Frame(8'333, messages::ImageEncoding::kRgb));
  EXPECT_EQ(node_.health().counter("clock_reset"), 1);
  EXPECT_EQ(node_.health().dropped(), 0);
  ASSERT_EQ(states_.size(), 7u);
  EXPECT_EQ(states_.back().utime, 8'333);
  // The new session confirms its tracks anew and goes on as before.
  for (int f = 2; f < 8; ++f) Send(Frame(8'333 * f, messages::ImageEncoding::kRgb));
  EXPECT_EQ(states_.back().num_balls, 3);
  EXPECT_EQ(node_.health().dropped(), 0);
}

TEST_F(EstimatorNodeTest, MoreBallsThanAMessageHoldsPublishesTheBestKnown) {
  // A 10 x 8 grid: more balls than messages::kMaxBalls, a state receivers would refuse whole.
  balls_.clear();
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 8; ++j) {
      const Eigen::Vector2d at(0.15 + 0.245 * i, 0.12 + 0.147 * j);
      balls_.push_back(
          render::RenderBall::AtRest(8 * i + j, render::PoolBallColour((i + j) % 16), at));
    }
  }
  // The same frames through an estimator of its own: how many balls there are to publish.
  estimator::BallEstimator alone(camera_, Pool());
  long beyond = 0;
  for (int f = 0; f < 8; ++f) {
    const image_t frame = Frame(1'000'000 + 8'333 * f, messages::ImageEncoding::kRgb);
    ASSERT_TRUE(alone.Process(messages::DecodeImage(frame).image, 1e-6 * frame.utime));
    beyond += std::max<long>(0, static_cast<long>(alone.Balls().size()) - messages::kMaxBalls);
    Send(frame);
  }
  ASSERT_GT(alone.Balls().size(), static_cast<std::size_t>(messages::kMaxBalls));
  ASSERT_EQ(states_.size(), 8u);
  EXPECT_EQ(states_.back().num_balls, messages::kMaxBalls);
  EXPECT_EQ(node_.health().counter("balls_not_published"), beyond);
  EXPECT_EQ(node_.health().dropped(), 0);
}

// A fixed camera's table is learnt once: frames of a still view never count a move, however the
// balls lie; when the camera is knocked (moved 4 cm along the table), NODE_STATUS says so and the
// node goes on.
TEST_F(EstimatorNodeTest, AMovedViewIsSaidInTheStatus) {
  std::int64_t utime = 1'000'000;
  for (int i = 0; i < 40; ++i) {
    balls_[1] = render::RenderBall::AtRest(3, render::PoolBallColour(3), {1.3 + 0.01 * i, 0.9});
    Send(Frame(utime += 8'333, messages::ImageEncoding::kRgb));
  }
  EXPECT_EQ(node_.health().counter("view_moved"), 0);
  camera::CameraModel knocked = camera_;
  knocked.translation += knocked.rotation * Eigen::Vector3d(0.04, 0, 0);
  const render::TableRenderer moved(knocked, Pool());
  for (int i = 0; i < 40; ++i) {
    utime += 8'333;
    Send(messages::EncodeImage(moved.Render(balls_, 1e-6 * utime), utime,
                               messages::ImageEncoding::kRgb));
  }
  EXPECT_EQ(node_.health().counter("view_moved"), 1);
  EXPECT_EQ(node_.frames(), 80);
  bool said = false;
  for (const std::string& line : log_) {
    said = said || line.find("view has moved") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

// A ball model that does not load, or is of other balls than --params', stops the node before
// it starts (2), as a camera file that does not load does.
TEST(EstimatorNodeCommand, ABallModelOfOtherBallsOrNoneIsAUsageError) {
  estimator::BallModel snooker;
  snooker.set = estimator::BallSet::kSnooker;
  snooker.identity = estimator::HandSetIdentity();
  const std::string path = ::testing::TempDir() + "snooker_balls.json";
  std::ofstream(path) << estimator::BallModelJson(snooker);
  EstimatorNodeCommandLine line;
  line.params = "pool";
  for (const std::string& model : {path, path + ".missing"}) {
    line.ball_model = model;
    EXPECT_EQ(RunEstimatorNodeCommand(line), 2) << model;
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace billiard::estimator_node
