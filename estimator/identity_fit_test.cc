// Identity's parameters fitted from known balls: the decision stump on analytic cases, and on the
// simulator's rendered pool balls (their paint known) under three lights, one camera each: the
// colours fitted are the renderer's paint, the stripes' threshold splits the stripes from the
// solids, and the parameters fitted on three lights name the balls under a fourth.
#include "estimator/identity_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "estimator/ball_detector.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

TEST(SplitShares, TheMiddleOfTheWidestGapWithTheFewestWrong) {
  // Apart: the middle of the gap between them.
  EXPECT_DOUBLE_EQ(*SplitShares({0.6, 0.7, 0.9}, {0.1, 0.2, 0.4}), 0.5);
  // One of `below` among `above`: no threshold puts all right; of the two that put one wrong,
  // the middle of the wider gap (0.3 to 0.6, not 0.65 to 0.7).
  EXPECT_DOUBLE_EQ(*SplitShares({0.6, 0.7, 0.9}, {0.1, 0.2, 0.3, 0.65}), 0.45);
  // Swapped sides: a threshold between them puts all four wrong, one at either end three.
  const double swapped = *SplitShares({0.1, 0.2}, {0.8, 0.9});
  EXPECT_TRUE(swapped < 0.2 || swapped > 0.8) << swapped;
  EXPECT_FALSE(SplitShares({}, {0.1}).has_value());
  EXPECT_FALSE(SplitShares({0.1}, {}).has_value());
}

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

// A light of another colour: every channel of the frame scaled.
cv::Mat Tinted(const cv::Mat& frame, const cv::Vec3f& tint) {
  std::vector<cv::Mat> channels;
  cv::split(frame, channels);
  for (int c = 0; c < 3; ++c) channels[c].convertTo(channels[c], CV_8U, tint[c]);
  cv::Mat out;
  cv::merge(channels, out);
  return out;
}

// The cue ball and the pool balls 1-15 in two rows, rendered overhead under a light of `tint`,
// at their projected centres and radius (the truth a detector would find), as known balls of
// `source`.
std::vector<KnownBall> RenderedRack(const cv::Vec3f& tint, int source, cv::Mat* frame = nullptr,
                                    std::vector<BallDetection>* detections = nullptr) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  render::RenderOptions options;
  options.exposure_s = 0;
  const render::TableRenderer renderer(camera, Pool(), options);
  std::vector<render::RenderBall> shown;
  std::vector<BallDetection> balls;
  const double radius = ExpectedRadiusPx(camera, Pool().ball.radius);
  for (int id = 0; id <= 15; ++id) {
    const Eigen::Vector2d where(0.3 + 0.24 * (id % 8), 0.4 + 0.5 * (id / 8));
    render::RenderBall ball = render::RenderBall::AtRest(id, render::PoolBallColour(id), where);
    ball.striped = render::PoolBallStriped(id);
    shown.push_back(ball);
    balls.push_back({camera.Project({where.x(), where.y(), Pool().ball.radius}), radius, 1.0});
  }
  const cv::Mat image = Tinted(renderer.Render(shown, 0.0), tint);
  const std::vector<BallLook> looks = LookAtBalls(image, balls, BallSet::kPool);
  std::vector<KnownBall> known;
  for (int id = 0; id <= 15; ++id) {
    known.push_back({looks[id], BallSet::kPool, id == 0 ? BallClass::kCue : PoolBall(id),
                     PoolGroup::kNone, source});
  }
  if (frame != nullptr) *frame = image;
  if (detections != nullptr) *detections = balls;
  return known;
}

// Three cameras, each under its own light.
std::vector<KnownBall> ThreeCameras() {
  std::vector<KnownBall> balls;
  int source = 0;
  for (const cv::Vec3f& tint :
       {cv::Vec3f(1, 1, 1), cv::Vec3f(0.85f, 1.0f, 1.1f), cv::Vec3f(1.1f, 1.0f, 0.85f)}) {
    const auto more = RenderedRack(tint, source++);
    balls.insert(balls.end(), more.begin(), more.end());
  }
  return balls;
}

double HueDegrees(const cv::Vec3f& lab) { return std::atan2(lab[2], lab[1]) * 180.0 / M_PI; }

TEST(FitIdentity, TheRenderersPaintIsTheColourFitted) {
  const IdentityFit fit = FitIdentity(ThreeCameras(), HandSetIdentity());
  EXPECT_EQ(fit.classes_fitted, 7);  // the solids' colours, which the stripes share
  int fitted = 0;
  for (const ColourPrototype& c : fit.parameters.colours) {
    if (c.table != BallSet::kPool) continue;
    ++fitted;
    const int number = static_cast<int>(c.ball_class);
    const cv::Vec3b bgr = render::PoolBallColour(number);
    const cv::Vec3f paint = LabOfSrgb({bgr[2], bgr[1], bgr[0]});
    double dh = std::abs(HueDegrees(c.lab) - HueDegrees(paint));
    dh = std::min(dh, 360 - dh);
    EXPECT_LT(dh, 10.0) << "the " << number << ": fitted " << c.lab << ", paint " << paint;
  }
  EXPECT_EQ(fitted, 7 * 3);  // one colour per camera and class
  // The other sets' colours were not shown: the hand-set ones stay.
  EXPECT_EQ(fit.classes_kept, 6 + 2);
}

TEST(FitIdentity, TheThresholdsSplitTheRenderedBalls) {
  const std::vector<KnownBall> balls = ThreeCameras();
  const IdentityFit fit = FitIdentity(balls, HandSetIdentity());
  EXPECT_TRUE(fit.cue_white && fit.cue_colour && fit.black_share && fit.stripe_plain);
  for (const KnownBall& b : balls) {
    const int number = static_cast<int>(b.ball_class);
    if (b.ball_class == BallClass::kCue) {
      EXPECT_GT(b.look.white, fit.parameters.cue_white);
      EXPECT_LT(b.look.colour, fit.parameters.cue_colour);
    } else if (number == 8) {
      EXPECT_GT(b.look.black, fit.parameters.black_share);
    } else {
      EXPECT_EQ(b.look.plain > fit.parameters.stripe_plain, number > 8) << "the " << number;
      EXPECT_LT(b.look.black, fit.parameters.black_share) << "the " << number;
    }
  }
}

TEST(FitIdentity, FittedOnThreeLightsItNamesTheBallsUnderAFourth) {
  const IdentityFit fit = FitIdentity(ThreeCameras(), HandSetIdentity());
  cv::Mat frame;
  std::vector<BallDetection> balls;
  RenderedRack({0.9f, 0.95f, 1.15f}, 3, &frame, &balls);
  const std::vector<BallIdentity> named =
      IdentifyBalls(frame, balls, BallSet::kPool, fit.parameters);
  for (int id = 0; id <= 15; ++id) {
    EXPECT_EQ(BallClassName(named[id].ball_class), id == 0 ? "cue" : std::to_string(id));
  }
}

TEST(FitIdentity, TooFewBallsKeepThePriors) {
  // Two cue balls and two solids: below kMinBallsPerSide on a side, no threshold is fitted; the
  // solids' colours are, their classes alone.
  std::vector<KnownBall> balls = RenderedRack({1, 1, 1}, 0);
  balls.resize(3);  // the cue ball, the 1 and the 2
  const IdentityFit fit = FitIdentity(balls, HandSetIdentity());
  EXPECT_FALSE(fit.cue_white || fit.cue_colour || fit.black_share || fit.stripe_plain);
  EXPECT_EQ(fit.parameters.cue_white, HandSetIdentity().cue_white);
  EXPECT_EQ(fit.parameters.stripe_plain, HandSetIdentity().stripe_plain);
  EXPECT_EQ(fit.classes_fitted, 2);
  std::set<int> pool_classes;
  for (const ColourPrototype& c : fit.parameters.colours) {
    if (c.table == BallSet::kPool) pool_classes.insert(static_cast<int>(c.ball_class));
  }
  EXPECT_EQ(pool_classes, (std::set<int>{1, 2, 3, 4, 5, 6, 7}));
  // Nothing known: the prior itself.
  const IdentityFit none = FitIdentity({}, HandSetIdentity());
  EXPECT_EQ(none.parameters.colours.size(), HandSetIdentity().colours.size());
  EXPECT_EQ(none.classes_fitted, 0);
}

}  // namespace
}  // namespace billiard::estimator
