// Ball identity on the simulator's rendered pool balls (their colours known): the cue ball, the
// black and each solid by number, under white light and under a tinted one (the white balance
// taken from the cue ball), and the snooker set's colours; a confidence in [0, 1] that is higher
// for a clear ball than for a doubtful one.
#include "estimator/ball_identity.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "estimator/ball_class.h"
#include "estimator/ball_detector.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

// The cue ball and the balls 1-8 in a row, rendered overhead, detected.
struct Rendered {
  cv::Mat frame;
  std::vector<BallDetection> balls;  // in the order of the row (0, 1, ..., 8)
};

Rendered RenderRow(const cv::Vec3f& tint) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  render::RenderOptions options;
  options.exposure_s = 0;
  const render::TableRenderer renderer(camera, Pool(), options);
  std::vector<render::RenderBall> shown;
  std::vector<Eigen::Vector2d> where;
  for (int id = 0; id <= 8; ++id) {
    where.push_back({0.3 + 0.24 * id, 0.5 + 0.1 * (id % 2)});
    shown.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id), where.back()));
  }
  Rendered r;
  r.frame = renderer.Render(shown, 0.0);
  // A light of another colour: every channel scaled.
  std::vector<cv::Mat> channels;
  cv::split(r.frame, channels);
  for (int c = 0; c < 3; ++c) channels[c].convertTo(channels[c], CV_8U, tint[c]);
  cv::merge(channels, r.frame);
  const double radius = ExpectedRadiusPx(camera, Pool().ball.radius);
  for (const Eigen::Vector2d& p : where) {
    r.balls.push_back({camera.Project({p.x(), p.y(), Pool().ball.radius}), radius, 1.0});
  }
  return r;
}

TEST(BallIdentity, TheCueBallTheBlackAndEverySolidUnderAnyLight) {
  for (const cv::Vec3f& tint : {cv::Vec3f(1, 1, 1), cv::Vec3f(0.8f, 1.0f, 1.15f),
                                cv::Vec3f(1.15f, 1.0f, 0.8f)}) {
    const Rendered r = RenderRow(tint);
    const auto identities = IdentifyBalls(r.frame, r.balls, BallSet::kPool);
    ASSERT_EQ(identities.size(), 9u);
    EXPECT_EQ(identities[0].ball_class, BallClass::kCue) << "tint " << tint;
    for (int number = 1; number <= 8; ++number) {
      EXPECT_EQ(BallClassName(identities[number].ball_class), std::to_string(number))
          << "tint " << tint;
    }
    for (const BallIdentity& id : identities) {
      EXPECT_GE(id.confidence, 0.0);
      EXPECT_LE(id.confidence, 1.0);
    }
    EXPECT_GT(identities[0].confidence, 0.5) << "tint " << tint;
  }
}

TEST(BallIdentity, SnookersColoursAndUnknownBeyondTheFrame) {
  const Rendered r = RenderRow({1, 1, 1});
  const auto snooker = IdentifyBalls(r.frame, r.balls, BallSet::kSnooker);
  EXPECT_EQ(snooker[0].ball_class, BallClass::kCue);
  EXPECT_EQ(snooker[1].ball_class, BallClass::kYellow);
  EXPECT_EQ(snooker[2].ball_class, BallClass::kBlue);
  EXPECT_EQ(snooker[3].ball_class, BallClass::kRed);
  EXPECT_EQ(snooker[6].ball_class, BallClass::kGreen);
  EXPECT_EQ(snooker[8].ball_class, BallClass::kBlack);
  // A ball whose disc is off the frame has no colour to go by.
  const auto off = IdentifyBalls(r.frame, {{{-100, -100}, 12.0, 1.0}}, BallSet::kPool);
  EXPECT_EQ(off[0].ball_class, BallClass::kUnknown);
  EXPECT_EQ(off[0].confidence, 0.0);
}

TEST(BallClass, NamesAndSets) {
  EXPECT_EQ(BallClassName(BallClass::kCue), "cue");
  EXPECT_EQ(BallClassName(PoolBall(11)), "11");
  EXPECT_EQ(BallClassName(BallClass::kPink), "pink");
  EXPECT_EQ(BallClassName(BallClass::kUnknown), "unknown");
  EXPECT_THROW(PoolBall(0), std::invalid_argument);
  EXPECT_THROW(PoolBall(16), std::invalid_argument);
  EXPECT_EQ(BallSetOf("snooker"), BallSet::kSnooker);
  EXPECT_EQ(BallSetOf("carom"), BallSet::kCarom);
  EXPECT_EQ(BallSetOf("pool"), BallSet::kPool);
  EXPECT_EQ(BallSetOf("paper"), BallSet::kPool);
}

}  // namespace
}  // namespace billiard::estimator
