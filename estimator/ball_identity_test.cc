// Ball identity on the simulator's rendered pool balls (their colours known): the cue ball, the
// black and each solid by number, under white light and under a tinted one (the white balance
// taken from the cue ball), and the snooker set's colours; a confidence in [0, 1] that is higher
// for a clear ball than for a doubtful one.
#include "estimator/ball_identity.h"

#include <gtest/gtest.h>

#include <map>
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

// The pool balls `ids` in a row, rendered overhead under a light of `tint`, detected.
Rendered RenderRow(const cv::Vec3f& tint,
                   const std::vector<int>& ids = {0, 1, 2, 3, 4, 5, 6, 7, 8}) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  render::RenderOptions options;
  options.exposure_s = 0;
  const render::TableRenderer renderer(camera, Pool(), options);
  std::vector<render::RenderBall> shown;
  std::vector<Eigen::Vector2d> where;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    where.push_back({0.3 + 0.24 * i, 0.5 + 0.1 * (i % 2)});
    shown.push_back(render::RenderBall::AtRest(static_cast<int>(i), render::PoolBallColour(ids[i]),
                                               where.back()));
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
  for (const cv::Vec3f& tint :
       {cv::Vec3f(1, 1, 1), cv::Vec3f(0.8f, 1.0f, 1.15f), cv::Vec3f(1.15f, 1.0f, 0.8f)}) {
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

// A rack holds one ball of each class: the classes are given all at once. Two white balls are not
// both the cue ball, two yellow solids (the renderer draws the 9 as the 1) are not both the 1, and
// nothing is named twice.
TEST(BallIdentity, ARackHasOneOfEachNumber) {
  const Rendered r = RenderRow({1, 1, 1}, {0, 1, 9, 0, 8, 3});
  const auto identities = IdentifyBalls(r.frame, r.balls, BallSet::kPool);
  ASSERT_EQ(identities.size(), 6u);
  std::map<BallClass, int> named;
  for (const BallIdentity& id : identities) {
    if (id.ball_class != BallClass::kUnknown) ++named[id.ball_class];
  }
  for (const auto& [ball_class, count] : named) {
    EXPECT_EQ(count, 1) << BallClassName(ball_class) << " named " << count << " times";
  }
  EXPECT_EQ(named[BallClass::kCue], 1);
  EXPECT_TRUE(identities[1].ball_class == PoolBall(1) || identities[2].ball_class == PoolBall(1));
  EXPECT_EQ(identities[4].ball_class, PoolBall(8));
  EXPECT_EQ(identities[5].ball_class, PoolBall(3));
  // Of the two white balls, the one not called the cue ball is named with no confidence to speak
  // of, or not at all.
  const int other_white = identities[0].ball_class == BallClass::kCue ? 3 : 0;
  EXPECT_LT(identities[other_white].confidence, 0.5);
  // Snooker has fifteen reds: three red balls are all red.
  const Rendered reds = RenderRow({1, 1, 1}, {0, 3, 3, 3});
  const auto snooker = IdentifyBalls(reds.frame, reds.balls, BallSet::kSnooker);
  ASSERT_EQ(snooker.size(), 4u);
  EXPECT_EQ(snooker[0].ball_class, BallClass::kCue);
  for (int i = 1; i < 4; ++i) EXPECT_EQ(snooker[i].ball_class, BallClass::kRed) << i;
}

// A pool ball drawn on a cloth, lit from the left: its brightness falls from the lit limb to a
// quarter of it at the far one (Lambert's law along the light's direction). A stripe's band runs
// up and down the middle (`band` of the ball's radius each side), its white caps left and right;
// or, seen along its axis (`cap_on`), its cap white out to kCapOnRadii and its band around it.
struct DrawnBall {
  cv::Vec3b srgb;       // the ball's colour, R, G, B
  bool stripe = false;  // white beyond the band
  double band = 1.0 / 3;
  bool cap_on = false;
};

// A band of +-30 degrees of latitude seen along its axis: the cap's edge at sin 60 degrees.
constexpr double kCapOnRadii = 0.866;

constexpr double kDrawnRadiusPx = 24;

cv::Mat DrawShadedBalls(const std::vector<DrawnBall>& balls, std::vector<BallDetection>* detected) {
  const int spacing = static_cast<int>(3 * kDrawnRadiusPx);
  cv::Mat frame(2 * spacing, spacing * static_cast<int>(balls.size() + 1), CV_8UC3,
                cv::Scalar(60, 120, 40));  // BGR: a green cloth
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const double cx = spacing * (i + 1.0), cy = spacing;
    for (int y = 0; y < frame.rows; ++y) {
      for (int x = 0; x < frame.cols; ++x) {
        const double dx = (x - cx) / kDrawnRadiusPx, dy = (y - cy) / kDrawnRadiusPx;
        if (dx * dx + dy * dy > 1) continue;
        const double light = 1.0 - 0.75 * (dx + 1) / 2;
        const bool white =
            balls[i].stripe && (balls[i].cap_on ? std::hypot(dx, dy) < kCapOnRadii
                                                : std::abs(dx) > balls[i].band);
        const cv::Vec3b& c = white ? cv::Vec3b(255, 255, 255) : balls[i].srgb;
        frame.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(c[2] * light),
                                              cv::saturate_cast<uchar>(c[1] * light),
                                              cv::saturate_cast<uchar>(c[0] * light));
      }
    }
    detected->push_back({{cx, cy}, kDrawnRadiusPx, 1.0});
  }
  return frame;
}

TEST(BallIdentity, TheConfidenceIsTheRacksNotTheBallsAlone) {
  // Two red solids alike: whichever is called the 3 (the rack has one), the other could be it as
  // well, so neither is sure of it, however plainly each looks a 3 (alone, its margin over its
  // next best class, the 7, is wide). Beside the cue ball alone, the same 3 is sure.
  const Rendered alone = RenderRow({1, 1, 1}, {0, 3});
  const auto one = IdentifyBalls(alone.frame, alone.balls, BallSet::kPool);
  ASSERT_EQ(one.size(), 2u);
  EXPECT_EQ(one[1].ball_class, PoolBall(3));
  EXPECT_GT(one[1].confidence, 0.5);
  const Rendered twins = RenderRow({1, 1, 1}, {0, 3, 3});
  const auto two = IdentifyBalls(twins.frame, twins.balls, BallSet::kPool);
  ASSERT_EQ(two.size(), 3u);
  const int three = two[1].ball_class == PoolBall(3) ? 1 : 2;
  EXPECT_EQ(two[three].ball_class, PoolBall(3));
  EXPECT_LT(two[three].confidence, 0.5);
  EXPECT_LT(two[3 - three].confidence, 0.5);
}

// Pool ball `number`'s colour as the renderer draws it (R, G, B).
cv::Vec3b RenderedSrgb(int number) {
  const cv::Vec3b bgr = render::PoolBallColour(number);
  return {bgr[2], bgr[1], bgr[0]};
}

// The cue ball and the solids 1-8 drawn plain, and the names they should be given.
struct DrawnBalls {
  std::vector<DrawnBall> balls;
  std::vector<std::string> names;
};

DrawnBalls CueBallAndSolids() {
  DrawnBalls drawn;
  for (int number = 0; number <= 8; ++number) {
    drawn.balls.push_back({RenderedSrgb(number), false});
    drawn.names.push_back(number == 0 ? "cue" : std::to_string(number));
  }
  return drawn;
}

// Each ball named as `names` says, in order; `context` tells a failure's case.
void ExpectNamed(const std::vector<BallIdentity>& identities,
                 const std::vector<std::string>& names, const std::string& context) {
  ASSERT_EQ(identities.size(), names.size()) << context;
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(BallClassName(identities[i].ball_class), names[i]) << "ball " << i << context;
  }
}

// A stripe's cap turned away from the light is dark grey, neither white nor black: it is still
// the stripe's white (its chroma is as small against its lightness as the lit cap's), and a
// solid's shaded side keeps its colour. The blue and the red each as a solid and as a stripe.
TEST(BallIdentity, AStripesWhiteInShadeStillMarksAStripe) {
  const cv::Vec3b blue(20, 50, 160), red(215, 30, 30);
  std::vector<BallDetection> detected;
  const cv::Mat frame = DrawShadedBalls({{{255, 255, 255}, false},
                                         {blue, false},
                                         {blue, true},
                                         {red, false},
                                         {red, true},
                                         {{10, 10, 10}, false}},
                                        &detected);
  ExpectNamed(IdentifyBalls(frame, detected, BallSet::kPool),
              {"cue", "2", "10", "3", "11", "8"}, "");
}

// A stripe turned with its band to the camera, its axis across the view: its caps show only at
// the limb, beyond 0.8 of its radius (a band of +-53 degrees of latitude seen side on), the right
// one in shade. Beside the solids, the one of its colour too, each is still a stripe, whichever
// comes first: the solids' limbs, shaded as they are, stay coloured.
TEST(BallIdentity, AStripeWhoseCapsShowOnlyAtTheLimb) {
  constexpr double kBandOn = 0.8;
  for (const bool stripes_first : {false, true}) {
    DrawnBalls drawn = CueBallAndSolids();
    for (const int number : {10, 11}) {
      const auto at = stripes_first ? 0 : drawn.balls.size();
      drawn.balls.insert(drawn.balls.begin() + at, {RenderedSrgb(number), true, kBandOn});
      drawn.names.insert(drawn.names.begin() + at, std::to_string(number));
    }
    std::vector<BallDetection> detected;
    const cv::Mat frame = DrawShadedBalls(drawn.balls, &detected);
    ExpectNamed(IdentifyBalls(frame, detected, BallSet::kPool), drawn.names,
                stripes_first ? ", the stripes first" : "");
  }
}

// A stripe seen cap on, its outline fitted to its cap's edge (the sharpest; mech_img0118's 14 was
// outlined at 0.82 of its radius): its disc is all white, and its band, the blue of the 10 and the
// red of the 11, shows just outside the outline. Each is named by its band, beside the solids of
// those colours; without it, neither would be named. (A band of the cloth's colour, the 14 on
// green cloth, is taken for the cloth: that stripe stays unnamed.)
TEST(BallIdentity, AStripeSeenCapOnIsNamedByTheBandAroundItsCap) {
  DrawnBalls drawn = CueBallAndSolids();
  for (const int number : {10, 11}) {
    drawn.balls.push_back({RenderedSrgb(number), true, 0.0, true});
    drawn.names.push_back(std::to_string(number));
  }
  std::vector<BallDetection> detected;
  const cv::Mat frame = DrawShadedBalls(drawn.balls, &detected);
  for (std::size_t i = 0; i < drawn.balls.size(); ++i) {
    if (drawn.balls[i].cap_on) detected[i].radius_px *= kCapOnRadii;
  }
  ExpectNamed(IdentifyBalls(frame, detected, BallSet::kPool), drawn.names, "");
}

// Sets differ: a TV set's 4 is pink, to be told from the 2 on camera (Aramith's TV balls), and
// the 7 is maroon in some sets and brown in others. Each alone beside the cue ball (no other ball
// to take the classes it could be taken for, the 3, the 7 or the 5) is named right.
TEST(BallIdentity, ATvSetsPinkFourAndABrownSeven) {
  for (const auto& [srgb, name] :
       {std::pair{cv::Vec3b(230, 80, 140), "4"}, std::pair{cv::Vec3b(140, 60, 20), "7"},
        std::pair{cv::Vec3b(125, 25, 35), "7"}}) {
    std::vector<BallDetection> detected;
    const cv::Mat frame = DrawShadedBalls({{{255, 255, 255}, false}, {srgb, false}}, &detected);
    const auto identities = IdentifyBalls(frame, detected, BallSet::kPool);
    ASSERT_EQ(identities.size(), 2u);
    EXPECT_EQ(identities[0].ball_class, BallClass::kCue);
    EXPECT_EQ(BallClassName(identities[1].ball_class), name) << srgb;
  }
}

// The rack's one of each number goes to the sure balls first: of two purple outlines beside the
// other solids, the one the detector doubts (a hand's shadow, say; score 0.4) does not take the 4
// from the sure one, whichever comes first.
TEST(BallIdentity, ADoubtfulOutlineDoesNotTakeASureBallsNumber) {
  for (const std::size_t doubtful : {3, 8}) {
    Rendered r = RenderRow({1, 1, 1}, {0, 2, 3, 4, 5, 6, 7, 8, 4});
    r.balls[doubtful].score = 0.4;
    const std::size_t sure = doubtful == 3 ? 8 : 3;
    const auto identities = IdentifyBalls(r.frame, r.balls, BallSet::kPool);
    ASSERT_EQ(identities.size(), 9u);
    EXPECT_EQ(identities[sure].ball_class, PoolBall(4)) << "doubtful " << doubtful;
    EXPECT_NE(identities[doubtful].ball_class, PoolBall(4)) << "doubtful " << doubtful;
  }
}

// A warm light on an ivory cue ball: its body is cream, its highlight clipped white. The highlight
// tells the sensor's limit, not the light's colour, so the white balance is taken from the body,
// and the ball is the cue ball, not one of English pool's yellows.
TEST(BallIdentity, AnIvoryCueBallWithAClippedHighlightUnderAWarmLight) {
  std::vector<BallDetection> detected;
  cv::Mat frame = DrawShadedBalls(
      {{{250, 215, 140}, false}, {{250, 210, 20}, false}, {{210, 30, 30}, false}}, &detected);
  const Eigen::Vector2d highlight = detected[0].pixel - Eigen::Vector2d(0.4 * kDrawnRadiusPx, 0);
  cv::circle(frame, cv::Point(static_cast<int>(highlight.x()), static_cast<int>(highlight.y())),
             static_cast<int>(0.35 * kDrawnRadiusPx), cv::Scalar(255, 255, 255), cv::FILLED);
  const auto identities = IdentifyBalls(frame, detected, BallSet::kBlackball);
  ASSERT_EQ(identities.size(), 3u);
  EXPECT_EQ(identities[0].ball_class, BallClass::kCue);
  EXPECT_EQ(identities[1].ball_class, BallClass::kYellow);
  EXPECT_EQ(identities[2].ball_class, BallClass::kRed);
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
