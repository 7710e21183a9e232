// The ball detector on the real photograph and on deterministic variants of it (an arm with a
// badge and a cue, extra shadows, projected light, noise, motion blur, another cloth colour), and
// its sub-pixel accuracy on anti-aliased synthetic frames whose ball centres are known exactly.
#include "estimator/ball_detector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "estimator/ball_identity.h"
#include "estimator/testing/real_table_photo.h"
#include "estimator/testing/synthetic_table.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/render/table_renderer.h"
#include "sim/table/rack.h"
#include "sim/table/table_geometry.h"
#include "tests/support/test_data.h"

namespace billiard::estimator {
namespace {

using testing::HandBall;
using testing::DrawTable;
using testing::kRealTablePhotoRadiusPx;
using testing::SyntheticBall;

// The tests on the real photograph, skipped with the reason where the test data is absent.
class RealPhoto : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string path = billiard::testing::TestDataPath(testing::kRealTablePhoto);
    if (path.empty()) GTEST_SKIP() << billiard::testing::MissingTestData(testing::kRealTablePhoto);
    photo_ = cv::imread(path, cv::IMREAD_COLOR);
    ASSERT_FALSE(photo_.empty()) << path;
  }
  cv::Mat Photo() const { return photo_.clone(); }

 private:
  cv::Mat photo_;
};

std::vector<BallDetection> DetectWithHint(const cv::Mat& image) {
  DetectorOptions options;
  options.ball_radius_px = kRealTablePhotoRadiusPx;
  return BallDetector(options).Detect(image);
}

// Every hand-listed ball found exactly once within 4 px, except those `covered` touches (they may
// be missed), and nothing else reported. `what` names the variant in failures.
void ExpectTheBalls(const std::vector<BallDetection>& found, const std::string& what,
                    const cv::Mat& covered = {}) {
  std::vector<int> matches(found.size(), 0);
  for (const HandBall& ball : testing::RealTablePhotoBalls()) {
    int times = 0;
    for (std::size_t i = 0; i < found.size(); ++i) {
      if ((found[i].pixel - ball.pixel).norm() < 4.0) {
        ++times;
        ++matches[i];
      }
    }
    bool hidden = false;
    if (!covered.empty()) {
      cv::Mat disc = cv::Mat::zeros(covered.size(), CV_8U);
      cv::circle(disc, cv::Point(ball.pixel.x(), ball.pixel.y()), 16, 255, cv::FILLED);
      hidden = cv::countNonZero(disc & covered) > 0;
    }
    if (hidden) {
      EXPECT_LE(times, 1) << what << ": " << ball.name << " at " << ball.pixel.transpose();
    } else {
      EXPECT_EQ(times, 1) << what << ": " << ball.name << " at " << ball.pixel.transpose();
    }
  }
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(matches[i], 1) << what << ": reported a ball at " << found[i].pixel.transpose()
                             << " (score " << found[i].score << ", radius " << found[i].radius_px
                             << ")";
  }
}

// Multiplies the image by `gain` where `mask` (CV_32F, 0..1) is set: shadows below 1, projected
// light (the cloth's own tint, brighter) above.
cv::Mat Relight(const cv::Mat& image, const cv::Mat& mask, double gain) {
  cv::Mat f, out;
  image.convertTo(f, CV_32FC3);
  cv::Mat factor = 1.0 + (gain - 1.0) * mask, factor3;
  cv::merge(std::vector<cv::Mat>{factor, factor, factor}, factor3);
  f = f.mul(factor3);
  f.convertTo(out, CV_8UC3);  // saturates, as a camera does
  return out;
}

TEST_F(RealPhoto, FindsEveryBallOfTheRealPhotographOnce) {
  const cv::Mat photo = Photo();
  ExpectTheBalls(DetectWithHint(photo), "radius hint");
  // Without a hint the radius comes from the blobs, and the same balls are found.
  BallDetector detector;
  ExpectTheBalls(detector.Detect(photo), "estimated radius");
  EXPECT_NEAR(detector.radius_px(), kRealTablePhotoRadiusPx, 1.0);
  // A grey copy: no hue, only brightness against the cloth. The dark balls stay findable; not
  // all are (a red ball is about as bright as the cloth's shadow), so only report.
  cv::Mat grey;
  cv::cvtColor(photo, grey, cv::COLOR_BGR2GRAY);
  const auto grey_balls = DetectWithHint(grey);
  std::fprintf(stderr, "grey copy: %zu balls found\n", grey_balls.size());
}

TEST_F(RealPhoto, IgnoresAnArmAndACueOverTheCloth) {
  const cv::Mat photo = Photo();
  cv::Mat image = photo.clone();
  cv::Mat covered = cv::Mat::zeros(photo.size(), CV_8U);
  // A forearm and hand reaching in from the bottom rail, shaded darker towards its sides.
  const std::vector<cv::Point> arm = {{760, 720}, {880, 720}, {845, 530},
                                      {815, 470}, {760, 462}, {722, 520}};
  cv::Mat arm_mask = cv::Mat::zeros(photo.size(), CV_8U), depth;
  cv::fillPoly(arm_mask, std::vector<std::vector<cv::Point>>{arm}, 255, cv::LINE_AA);
  cv::distanceTransform(arm_mask, depth, cv::DIST_L2, 3);
  // The cue: a tapered wooden shaft from off the image to just short of the white ball, with a
  // lighter stripe along it.
  const Eigen::Vector2d tip(566, 592), butt(1000, 800);
  const Eigen::Vector2d along = (tip - butt).normalized(), across(-along.y(), along.x());
  const double tip_half = 3.5, butt_half = 9.0, length = (tip - butt).norm();
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      cv::Vec3b& p = image.at<cv::Vec3b>(y, x);
      const Eigen::Vector2d q = Eigen::Vector2d(x, y) - butt;
      const double t = q.dot(along) / length, side = q.dot(across);
      const double half = butt_half + (tip_half - butt_half) * t;
      if (t >= 0 && t <= 1 && std::abs(side) <= half) {
        const double shade = 0.75 + 0.35 * (1 - std::abs(side) / half);
        p = cv::Vec3b(cv::saturate_cast<uint8_t>(55 * shade),
                      cv::saturate_cast<uint8_t>(120 * shade),
                      cv::saturate_cast<uint8_t>(185 * shade));
        covered.at<uint8_t>(y, x) = 255;
      }
      if (arm_mask.at<uint8_t>(y, x) > 0) {
        const double shade = 0.55 + 0.45 * std::min(1.0, depth.at<float>(y, x) / 30.0);
        const double a = arm_mask.at<uint8_t>(y, x) / 255.0;
        const cv::Vec3d skin = cv::Vec3d(125, 160, 215) * shade;
        for (int c = 0; c < 3; ++c) {
          p[c] = cv::saturate_cast<uint8_t>(a * skin[c] + (1 - a) * p[c]);
        }
        covered.at<uint8_t>(y, x) = 255;
      }
    }
  }
  // A round white badge on the forearm, shaded like a ball: a logo on a sleeve, a watch's face.
  const Eigen::Vector2d badge(795, 560);
  for (int y = 540; y <= 580; ++y) {
    for (int x = 775; x <= 815; ++x) {
      const double rho = (Eigen::Vector2d(x, y) - badge).norm() / kRealTablePhotoRadiusPx;
      if (rho > 1) continue;
      const double shade = 0.6 + 0.4 * std::sqrt(1 - rho * rho);
      image.at<cv::Vec3b>(y, x) = cv::Vec3b::all(cv::saturate_cast<uint8_t>(240 * shade));
    }
  }
  const auto found = DetectWithHint(image);
  ExpectTheBalls(found, "arm and cue", covered);
  for (const auto& ball : found) {
    EXPECT_EQ(
        covered.at<uint8_t>(static_cast<int>(ball.pixel.y()), static_cast<int>(ball.pixel.x())), 0)
        << "a ball reported on the arm or the cue at " << ball.pixel.transpose();
  }
}

TEST_F(RealPhoto, IgnoresShadowsAndProjectedLight) {
  const cv::Mat photo = Photo();
  // Shadows: soft darker patches of cloth, ball-sized and larger.
  cv::Mat shadow = cv::Mat::zeros(photo.size(), CV_32F);
  cv::ellipse(shadow, {850, 300}, {40, 25}, 20, 0, 360, 1.0, cv::FILLED);
  cv::ellipse(shadow, {620, 150}, {16, 14}, 0, 0, 360, 1.0, cv::FILLED);
  cv::ellipse(shadow, {300, 560}, {50, 30}, -10, 0, 360, 1.0, cv::FILLED);
  cv::GaussianBlur(shadow, shadow, {0, 0}, 2.0);
  const cv::Mat shadowed = Relight(photo, shadow, 0.55);
  ExpectTheBalls(DetectWithHint(shadowed), "extra shadows");

  // Projected light: the cloth's own colour, brighter, in discs of ball size and larger and in
  // thin lines; flat, as light on a flat cloth is.
  cv::Mat light = cv::Mat::zeros(photo.size(), CV_32F);
  cv::circle(light, {850, 150}, 15, 1.0, cv::FILLED, cv::LINE_AA);
  cv::circle(light, {600, 320}, 25, 1.0, cv::FILLED, cv::LINE_AA);
  cv::circle(light, {1000, 320}, 40, 1.0, cv::FILLED, cv::LINE_AA);
  cv::circle(light, {350, 500}, 15, 1.0, cv::FILLED, cv::LINE_AA);
  cv::line(light, {300, 150}, {500, 300}, 1.0, 3, cv::LINE_AA);
  cv::line(light, {600, 470}, {880, 520}, 1.0, 2, cv::LINE_AA);
  for (const double gain : {1.5, 1.8}) {
    ExpectTheBalls(DetectWithHint(Relight(photo, light, gain)),
                   "projected light x" + std::to_string(gain));
  }
}

TEST_F(RealPhoto, SurvivesNoiseAndMotionBlur) {
  const cv::Mat photo = Photo();
  cv::Mat noise(photo.size(), CV_16SC3), noisy;
  cv::RNG rng(7);
  rng.fill(noise, cv::RNG::NORMAL, 0, 8);
  cv::Mat wide;
  photo.convertTo(wide, CV_16SC3);
  cv::Mat sum = wide + noise;
  sum.convertTo(noisy, CV_8UC3);
  ExpectTheBalls(DetectWithHint(noisy), "gaussian noise, sigma 8");

  // A horizontal smear over 9 px (a fast pan or a long exposure).
  cv::Mat blurred;
  cv::filter2D(photo, blurred, -1, cv::Mat::ones(1, 9, CV_32F) / 9.0);
  ExpectTheBalls(DetectWithHint(blurred), "motion blur, 9 px");
}

TEST_F(RealPhoto, LearnsAnotherClothColourAndLight) {
  // The whole frame's hue turned by 60 degrees (the cloth goes blue) and its brightness scaled by
  // 0.7: nothing in the detector may depend on this photo's colours.
  cv::Mat hsv;
  cv::cvtColor(Photo(), hsv, cv::COLOR_BGR2HSV);
  for (auto it = hsv.begin<cv::Vec3b>(); it != hsv.end<cv::Vec3b>(); ++it) {
    (*it)[0] = static_cast<uint8_t>(((*it)[0] + 30) % 180);
    (*it)[2] = static_cast<uint8_t>(std::lround((*it)[2] * 0.7));
  }
  cv::Mat recoloured;
  cv::cvtColor(hsv, recoloured, cv::COLOR_HSV2BGR);
  ExpectTheBalls(DetectWithHint(recoloured), "blue cloth, 0.7 brightness");
  BallDetector detector;
  ExpectTheBalls(detector.Detect(recoloured), "blue cloth, estimated radius");
}

TEST(BallDetector, SubPixelCentresOnSyntheticFrames) {
  // About 2 mm per pixel: a 52.5 mm ball is 13 px in radius.
  const double radius = 13.1;
  const cv::Size size(800, 480);
  const cv::Rect cloth(40, 40, 720, 400);
  const std::vector<cv::Vec3d> colours = {{30, 30, 200},  {235, 235, 235}, {20, 20, 25},
                                          {200, 120, 20}, {20, 180, 230},  {150, 120, 230}};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  double sum_squares = 0;
  int count = 0, refine_count = 0;
  double refine_squares = 0;
  for (int frame = 0; frame < 4; ++frame) {
    std::vector<SyntheticBall> balls;
    // A grid of isolated balls at random sub-pixel offsets, a touching pair, and a ball against
    // the cushion.
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 3; ++j) {
        balls.push_back({{130 + 150 * i + 20 * fraction(rng), 110 + 110 * j + 20 * fraction(rng)},
                         colours[(i + j + frame) % colours.size()]});
      }
    }
    const double angle = 2 * M_PI * fraction(rng);
    const Eigen::Vector2d pair(690 + fraction(rng), 160 + fraction(rng));
    balls.push_back({pair, colours[0]});
    balls.push_back(
        {pair + 2 * radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)), colours[1]});
    balls.push_back({{690 + fraction(rng), cloth.y + radius + 0.2 * fraction(rng)}, colours[3]});
    const cv::Mat image = DrawTable(balls, radius, size, cloth, 4.0, 100 + frame);

    DetectorOptions options;
    options.ball_radius_px = radius;
    BallDetector detector(options);
    const auto found = detector.Detect(image);
    EXPECT_EQ(found.size(), balls.size()) << "frame " << frame;
    for (const SyntheticBall& b : balls) {
      const BallDetection* nearest = nullptr;
      for (const auto& d : found) {
        if (!nearest || (d.pixel - b.centre).norm() < (nearest->pixel - b.centre).norm())
          nearest = &d;
      }
      ASSERT_NE(nearest, nullptr);
      const double error = (nearest->pixel - b.centre).norm();
      EXPECT_LT(error, 0.5) << "ball at " << b.centre.transpose() << ", frame " << frame;
      EXPECT_NEAR(nearest->radius_px, radius, 1.0);
      sum_squares += error * error;
      ++count;
      // The tracker's call: a prediction 3 px off.
      const auto refined = detector.RefineAt(image, b.centre + Eigen::Vector2d(2.4, -1.8), radius);
      ASSERT_TRUE(refined.has_value()) << "ball at " << b.centre.transpose();
      refine_squares += (refined->pixel - b.centre).squaredNorm();
      ++refine_count;
    }
  }
  const double rms = std::sqrt(sum_squares / count),
               refine_rms = std::sqrt(refine_squares / refine_count);
  std::fprintf(stderr, "centre error RMS: Detect %.3f px, RefineAt %.3f px over %d balls\n", rms,
               refine_rms, count);
  EXPECT_LT(rms, 0.2);
  EXPECT_LT(refine_rms, 0.2);
}

TEST(BallDetector, TablePositionsFromRenderedFramesWithinHalfAMillimetre) {
  // The simulator's renderer (sim/render/table_renderer.h): a pool table seen from 2.5 m, about
  // 2.2 mm per pixel, balls scattered at random (some against the cushions), sensor noise, shading
  // and contact shadows. The estimator needs 0.5 mm RMS on the table.
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double r = params.ball.radius;
  const camera::CameraModel camera = camera::CameraModel::Overhead(params.table, 1280, 720);
  render::RenderOptions render;
  render.exposure_s = 0;
  std::mt19937 rng(5);
  double sum_squares = 0;
  int count = 0;
  for (int frame = 0; frame < 3; ++frame) {
    render.seed = 20 + frame;
    const render::TableRenderer renderer(camera, params, render);
    std::vector<render::RenderBall> balls;
    std::vector<Eigen::Vector2d> truth;
    std::uniform_real_distribution<double> x(r, params.table.length - r),
        y(r, params.table.width - r);
    while (truth.size() < 16) {
      Eigen::Vector2d p(x(rng), y(rng));
      if (truth.size() < 2) p.y() = truth.empty() ? r : params.table.width - r;  // on a cushion
      const bool free = std::none_of(truth.begin(), truth.end(), [&](const Eigen::Vector2d& q) {
        return (q - p).norm() < 2.2 * r;
      });
      if (!free) continue;
      truth.push_back(p);
      balls.push_back(render::RenderBall::AtRest(
          static_cast<int>(truth.size()) - 1,
          render::PoolBallColour(static_cast<int>(truth.size()) - 1), p));
    }
    const cv::Mat image = renderer.Render(balls, 0.0);
    DetectorOptions options;
    options.ball_radius_px = ExpectedRadiusPx(camera, r);
    const auto found = BallDetector(options).Detect(image);
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const Eigen::Vector2d& p = truth[i];
      double best = 1e9;
      for (const auto& d : found)
        best = std::min(best, (camera.Unproject(d.pixel, r).head<2>() - p).norm());
      const double to_cushion =
          std::min({p.x(), p.y(), params.table.length - p.x(), params.table.width - p.y()});
      // Known limit, reported but not held to the target: balls within a radius of the cushion,
      // whose dark inner face the outline meets (0.3-1.2 mm, once 5 mm). Pool's greens (6, 14),
      // the cloth's hue and darker, are held to it: the rim's contrast still finds them.
      const bool at_cushion = to_cushion < 2 * r;
      std::fprintf(stderr, "  ball %2d%s: %.3f mm\n", balls[i].id, at_cushion ? " (cushion)" : "",
                   1e3 * best);
      if (at_cushion) continue;
      EXPECT_LT(best, 1.5e-3) << "ball at " << p.transpose() << ", frame " << frame;
      sum_squares += best * best;
      ++count;
    }
  }
  const double rmse = std::sqrt(sum_squares / count);
  std::fprintf(stderr, "rendered frames: table position RMSE %.3f mm over %d balls (%.2f mm/px)\n",
               1e3 * rmse, count, 1e3 * camera.MetresPerPixel({1.27, 0.635, r}));
  EXPECT_LT(rmse, 0.5e-3);
}

TEST(BallDetector, BallsInThePocketsJawsButNotThePocketsMouths) {
  // A rendered pool table with the corner pockets' mouths drawn beyond the cushions' noses (a dark
  // hole ringed by its liner's rim, as a camera sees one between the jaws), and a ball resting in
  // two of the four corners' jaws, 4 mm off both cushions: both balls are found (within half a
  // radius: a ball against a cushion is found less exactly, see above), nothing in the mouths.
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double r = params.ball.radius;
  const camera::CameraModel camera = camera::CameraModel::Overhead(params.table, 1280, 720);
  render::RenderOptions render;
  render.exposure_s = 0;
  render.seed = 7;
  const double length = params.table.length, width = params.table.width;
  const std::vector<Eigen::Vector2d> corners = {{0, 0}, {length, 0}, {length, width}, {0, width}};
  const std::vector<Eigen::Vector2d> truth = {{r + 4e-3, r + 4e-3},
                                              {length - r - 4e-3, width - r - 4e-3}};
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    balls.push_back(render::RenderBall::AtRest(
        static_cast<int>(i) + 1, render::PoolBallColour(static_cast<int>(i) + 1), truth[i]));
  }
  cv::Mat image = render::TableRenderer(camera, params, render).Render(balls, 0.0);
  const double radius_px = ExpectedRadiusPx(camera, r);
  for (const Eigen::Vector2d& corner : corners) {
    // 0.35 ball radii beyond both noses: its rim touches a ball in the jaws (2.1 radii away).
    const Eigen::Vector2d outward((corner.x() > 0 ? 1 : -1), (corner.y() > 0 ? 1 : -1));
    const Eigen::Vector2d mouth = corner + 0.35 * r * outward;
    const Eigen::Vector2d pixel = camera.Project({mouth.x(), mouth.y(), 0.0});
    const cv::Point centre(static_cast<int>(std::lround(pixel.x())),
                           static_cast<int>(std::lround(pixel.y())));
    cv::circle(image, centre, static_cast<int>(std::lround(1.1 * radius_px)),
               cv::Scalar(70, 70, 70), cv::FILLED, cv::LINE_AA);
    cv::circle(image, centre, static_cast<int>(std::lround(0.9 * radius_px)),
               cv::Scalar(12, 12, 12), cv::FILLED, cv::LINE_AA);
  }
  DetectorOptions options;
  options.ball_radius_px = radius_px;
  const auto found = BallDetector(options).Detect(image);
  for (const Eigen::Vector2d& p : truth) {
    const bool seen = std::any_of(found.begin(), found.end(), [&](const BallDetection& d) {
      return (camera.Unproject(d.pixel, r).head<2>() - p).norm() < 0.5 * r;
    });
    EXPECT_TRUE(seen) << "the ball in the jaws at " << p.transpose();
  }
  for (const BallDetection& d : found) {
    const Eigen::Vector2d on_table = camera.Unproject(d.pixel, r).head<2>();
    const bool a_ball = std::any_of(truth.begin(), truth.end(), [&](const Eigen::Vector2d& p) {
      return (on_table - p).norm() < r;
    });
    EXPECT_TRUE(a_ball) << "reported a ball at " << d.pixel.transpose() << " (score " << d.score
                        << ")";
  }
}

TEST(BallDetector, BallsAgainstTheNearCushionFoundFromTheirVisiblePart) {
  // A camera beyond the near rail (the synthetic suite's side view: 2 m from the table's middle,
  // 35 degrees up) sees the near cushion's nose, 36 mm high, hide the lower part of each ball
  // against it (the renderer hides what lies beyond the cushions, table_renderer.h): a quarter of
  // the ball's outline is the nose's straight edge, not the ball's. Each is found (without the nose
  // as an occluder the one at x = 0.45 was not, and the others were 0.2-0.9 px off), its centre
  // within 1.5 px of the projection of its true centre: a sphere off the axis of this wide lens
  // (69 degrees across) projects to an ellipse stretched away from the image's centre (14 % at the
  // frame's sides), which a circle fitted to its top three quarters follows (1.0-1.3 px at x = 0.45
  // and 1.95, 0.3 px nearer the axis). The balls in the open, outlined whole, are within 0.2 px.
  constexpr double kCutBallPx = 1.5, kOpenBallPx = 0.25;
  const physics::ModelParameters params = params::LoadParameters("pool");
  const double r = params.ball.radius, length = params.table.length, width = params.table.width;
  const Eigen::Vector3d middle(0.5 * length, 0.5 * width, 0.0);
  const double elevation = 35.0 * M_PI / 180.0;
  const camera::CameraModel camera = camera::CameraModel::LookingAt(
      middle + 2.0 * Eigen::Vector3d(0, -std::cos(elevation), std::sin(elevation)), middle, 1280,
      720, 1.2);
  render::RenderOptions render;
  render.exposure_s = 0;
  render.seed = 11;
  std::vector<Eigen::Vector2d> truth;
  for (const double x : {0.45, 0.85, 1.55, 1.95}) truth.push_back({x, r});  // against the nose
  for (const double x : {0.6, 1.0, 1.4, 1.8}) truth.push_back({x, 0.55});   // in the open
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const int id = static_cast<int>(i) + 1;
    balls.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id), truth[i]));
  }
  const cv::Mat image = render::TableRenderer(camera, params, render).Render(balls, 0.0);
  const auto found = BallDetector().Detect(image);
  for (const Eigen::Vector2d& p : truth) {
    const bool against_nose = p.y() < 2 * r;
    const Eigen::Vector2d pixel = camera.Project({p.x(), p.y(), r});
    double best = 1e9;
    for (const BallDetection& d : found) best = std::min(best, (d.pixel - pixel).norm());
    std::fprintf(stderr, "  ball at (%.2f, %.3f): %.2f px\n", p.x(), p.y(), best);
    EXPECT_LT(best, against_nose ? kCutBallPx : kOpenBallPx) << "the ball at " << p.transpose();
  }
  EXPECT_EQ(found.size(), truth.size());
}

TEST(BallDetector, EveryBallOfARackIsSureOnTheFirstFrame) {
  // The loop's break (run_loop.sh --scene break): the eight-ball racks of seeds 1-8 rendered as
  // table_sim_node renders them (overhead, 1280x720, JPEG at quality 90), the camera's radius
  // given. A ball scoring below sure waits three frames for the tracker, so each must be sure on
  // the first: the black in the middle, dark against the contact shadows it shares with six
  // bright neighbours, scored 0.80-0.93 on the votes at their reduced resolution, and 0.795 on
  // seed 4.
  constexpr double kSure = 0.8;  // TrackerOptions::sure_score
  const physics::ModelParameters params = params::LoadParameters("pool");
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const camera::CameraModel camera = camera::CameraModel::Overhead(params.table, 1280, 720);
  const render::TableRenderer renderer(camera, params);
  DetectorOptions options;
  options.ball_radius_px = ExpectedRadiusPx(camera, params.ball.radius);
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto rack =
        table::Rack(table::RackKind::kEightBall, geometry, params.ball.radius, seed);
    std::vector<render::RenderBall> shown;
    for (const table::SceneBall& ball : rack) {
      shown.push_back(render::RenderBall::AtRest(ball.id, render::PoolBallColour(ball.id),
                                                 ball.state.head<2>()));
      shown.back().striped = render::PoolBallStriped(ball.id);
    }
    std::vector<uchar> jpeg;
    cv::imencode(".jpg", renderer.Render(shown, 0.0), jpeg, {cv::IMWRITE_JPEG_QUALITY, 90});
    const auto found = BallDetector(options).Detect(cv::imdecode(jpeg, cv::IMREAD_COLOR));
    EXPECT_EQ(found.size(), rack.size()) << "seed " << seed;
    for (const table::SceneBall& ball : rack) {
      const Eigen::Vector2d pixel = camera.Project({ball.state.x(), ball.state.y(), params.ball.radius});
      const BallDetection* nearest = nullptr;
      for (const BallDetection& d : found) {
        if (!nearest || (d.pixel - pixel).norm() < (nearest->pixel - pixel).norm()) nearest = &d;
      }
      ASSERT_NE(nearest, nullptr);
      EXPECT_LT((nearest->pixel - pixel).norm(), 1.0) << "seed " << seed << ", ball " << ball.id;
      EXPECT_GE(nearest->score, kSure) << "seed " << seed << ", ball " << ball.id;
    }
  }
}

// What `billiard bench-detect --cross-validate` relies on: the balls' looks in the frame the
// detector searched (SearchedFrame, smoothed here: the camera is noisy) named under other identity
// parameters are what the detector names with those parameters, its balls unchanged. The other
// parameters swap the 2's and the 3's colours, so that the names do change.
TEST(BallDetector, NamesUnderOtherParametersAsItsBallsLooksSay) {
  const physics::ModelParameters params = params::LoadParameters("pool");
  const camera::CameraModel camera = camera::CameraModel::Overhead(params.table, 1280, 720);
  render::RenderOptions render;
  render.exposure_s = 0;
  render.noise_sigma = 8;
  std::vector<render::RenderBall> shown;
  for (int id = 0; id <= 8; ++id) {
    shown.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id),
                                               {0.3 + 0.24 * id, 0.5 + 0.1 * (id % 2)}));
  }
  const cv::Mat image = render::TableRenderer(camera, params, render).Render(shown, 0.0);
  IdentityParameters swapped = HandSetIdentity();
  for (ColourPrototype& c : swapped.colours) {
    if (c.table != BallSet::kPool) continue;
    if (c.ball_class == PoolBall(2)) {
      c.ball_class = PoolBall(3);
    } else if (c.ball_class == PoolBall(3)) {
      c.ball_class = PoolBall(2);
    }
  }
  BallDetector by_hand;
  const std::vector<BallDetection> found = by_hand.Detect(image);
  ASSERT_EQ(found.size(), shown.size());
  ASSERT_FALSE(by_hand.SearchedFrame(image).empty());
  EXPECT_GT(cv::norm(by_hand.SearchedFrame(image), image, cv::NORM_INF), 0) << "not smoothed";
  DetectorOptions options;
  options.identity = swapped;
  const std::vector<BallDetection> with_swapped = BallDetector(options).Detect(image);
  const std::vector<BallIdentity> named = NameBalls(
      LookAtBalls(by_hand.SearchedFrame(image), found, BallSet::kPool), found, BallSet::kPool,
      swapped);
  ASSERT_EQ(with_swapped.size(), found.size());
  int changed = 0;
  for (std::size_t i = 0; i < found.size(); ++i) {
    EXPECT_EQ(with_swapped[i].pixel, found[i].pixel);
    EXPECT_EQ(with_swapped[i].score, found[i].score);
    EXPECT_EQ(with_swapped[i].ball_class, named[i].ball_class) << "ball " << i;
    EXPECT_EQ(with_swapped[i].class_confidence, named[i].confidence) << "ball " << i;
    changed += with_swapped[i].ball_class != found[i].ball_class;
  }
  EXPECT_EQ(changed, 2);
}

TEST_F(RealPhoto, TimePerFrame) {
  const cv::Mat photo = Photo();
  DetectorOptions options;
  options.ball_radius_px = kRealTablePhotoRadiusPx;
  BallDetector detector(options);
  using Clock = std::chrono::steady_clock;
  auto start = Clock::now();
  detector.LearnTable(photo);
  const double learn_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  std::vector<BallDetection> balls;
  constexpr int kFrames = 30;
  std::vector<double> detect_ms;
  for (int i = 0; i < kFrames; ++i) {
    start = Clock::now();
    balls = detector.Detect(photo);
    detect_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  std::vector<double> refine_us;
  for (int i = 0; i < 10; ++i) {
    for (const auto& b : balls) {
      start = Clock::now();
      const auto refined = detector.RefineAt(photo, b.pixel + Eigen::Vector2d(2, -1), b.radius_px);
      refine_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
      EXPECT_TRUE(refined.has_value());
    }
  }
  std::sort(detect_ms.begin(), detect_ms.end());
  std::sort(refine_us.begin(), refine_us.end());
  std::fprintf(stderr,
               "1280x720, %zu balls: LearnTable %.2f ms, Detect median %.2f ms (min %.2f), "
               "RefineAt median %.1f us (min %.1f)\n",
               balls.size(), learn_ms, detect_ms[kFrames / 2], detect_ms[0],
               refine_us[refine_us.size() / 2], refine_us[0]);
  EXPECT_EQ(balls.size(), 21u);
}

}  // namespace
}  // namespace billiard::estimator
