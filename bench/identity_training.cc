#include "bench/identity_training.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "estimator/ball_identity.h"
#include "estimator/identity_parameters.h"
#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/render/table_renderer.h"
#include "sim/table/rack.h"
#include "sim/table/seeded_uniform.h"

namespace billiard::bench {

namespace {

using estimator::BallClass;
using estimator::BallSet;

// The drawn conditions' ranges (the header says why each).
constexpr double kMinRadiusPx = 8, kMaxRadiusPx = 40;
constexpr double kMinElevation = 25 * M_PI / 180, kMaxElevation = 85 * M_PI / 180;
constexpr double kMinDistance = 1.5, kMaxDistance = 3.0;  // camera to the table's middle [m]
constexpr double kCueLeftOut = 0.25;                      // share of frames without the cue ball
constexpr double kMaxHueTurn = 20 * M_PI / 180;
constexpr double kMaxBlurPx = 1.2;
constexpr double kMinNoise = 1, kMaxNoise = 4;
constexpr int kMinJpegQuality = 40, kMaxJpegQuality = 95;
constexpr double kMinStrength = 0.45, kMaxStrength = 1.25;
constexpr double kMaxLightTilt = 35 * M_PI / 180;
// A tungsten bulb's blue and green against daylight's (table_renderer.h), and a white balance's
// error either way on each channel.
constexpr double kTungstenBlue = 0.55, kTungstenGreen = 0.8, kTint = 0.1;
// How sets' balls differ from the hand-set colours: L* scaled by up to 12 %, chroma by up to
// 15 %, hue turned by up to 8 degrees.
constexpr double kLightnessSpread = 0.12, kChromaSpread = 0.15, kHueSpread = 8 * M_PI / 180;
// The detector's outlines against the truth: centre within 8 % of the radius, radius -10..+8 %.
constexpr double kCentreJitter = 0.08, kMinRadiusScale = 0.90, kMaxRadiusScale = 1.08;
// Balls placed at least this far apart [m], and kept kEdgeRadii radii inside the image.
constexpr double kClearance = 2e-3, kEdgeRadii = 1.5;
constexpr int kPlacementTries = 400;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

// Every ball of a set: its classes, the set's count of each, the cue ball first.
std::vector<BallClass> RackOf(BallSet set) {
  std::vector<BallClass> rack;
  for (const BallClass c : estimator::ClassesIn(set)) rack.insert(rack.end(), CountIn(set, c), c);
  return rack;
}

cv::Vec3b BgrOfLab(const cv::Vec3f& lab) {
  cv::Mat in(1, 1, CV_32FC3, cv::Scalar(lab[0], lab[1], lab[2])), out;
  cv::cvtColor(in, out, cv::COLOR_Lab2BGR);
  const cv::Vec3f bgr = out.at<cv::Vec3f>(0, 0);
  return {cv::saturate_cast<std::uint8_t>(255 * bgr[0]), cv::saturate_cast<std::uint8_t>(255 * bgr[1]),
          cv::saturate_cast<std::uint8_t>(255 * bgr[2])};
}

// A ball of `ball_class`'s colour in some set: the cue ball ivory to white, a black ball nearly
// black, any other one of its class's hand-set colours, varied.
cv::Vec3b BallColour(BallClass ball_class, BallSet set, table::SeededUniform* u) {
  const bool black = ball_class == BallClass::kBlack ||
                     (set == BallSet::kPool && ball_class == estimator::PoolBall(8));
  if (ball_class == BallClass::kCue) return BgrOfLab({float(u->Between(88, 98)), 0, float(u->Between(0, 12))});
  if (black) return BgrOfLab({float(u->Between(5, 20)), 0, 0});
  const BallSet table = estimator::ColourTableOf(set);
  const BallClass colour_class = estimator::ColourClassOf(ball_class, set);
  std::vector<cv::Vec3f> choices;
  for (const auto& c : estimator::HandSetIdentity().colours) {
    if (c.table == table && c.ball_class == colour_class) choices.push_back(c.lab);
  }
  const cv::Vec3f lab = choices[u->Below(choices.size())];
  const double chroma = std::hypot(lab[1], lab[2]) * (1 + u->Between(-kChromaSpread, kChromaSpread));
  const double hue = std::atan2(lab[2], lab[1]) + u->Between(-kHueSpread, kHueSpread);
  return BgrOfLab({float(std::clamp(lab[0] * (1 + u->Between(-kLightnessSpread, kLightnessSpread)), 5.0, 98.0)),
                   float(chroma * std::cos(hue)), float(chroma * std::sin(hue))});
}

Eigen::Vector3d RandomDirection(table::SeededUniform* u) {
  const double z = u->Between(-1, 1), angle = u->Between(0, 2 * M_PI);
  const double s = std::sqrt(1 - z * z);
  return {s * std::cos(angle), s * std::sin(angle), z};
}

// A ball of `ball_class` turned at random: a pool ball's number on its band.
render::RenderBall TurnedBall(BallClass ball_class, BallSet set, const Eigen::Vector2d& xy,
                              table::SeededUniform* u) {
  render::RenderBall ball = render::RenderBall::AtRest(0, BallColour(ball_class, set, u), xy);
  if (set != BallSet::kPool || ball_class == BallClass::kCue) return ball;
  ball.striped = static_cast<int>(ball_class) > 8;
  ball.axis = RandomDirection(u);
  ball.spot = ball.axis.cross(RandomDirection(u)).normalized();
  return ball;
}

// The camera (header): its elevation, azimuth and distance drawn, its field of view set by the
// ball's radius in pixels.
camera::CameraModel DrawCamera(const IdentityTrainingOptions& options, table::SeededUniform* u) {
  const auto& table = Pool().table;
  const Eigen::Vector3d middle(table.length / 2, table.width / 2, 0);
  const double elevation = u->Between(kMinElevation, kMaxElevation);
  const double azimuth = u->Between(0, 2 * M_PI), distance = u->Between(kMinDistance, kMaxDistance);
  const double radius_px = u->Between(kMinRadiusPx, kMaxRadiusPx);
  const Eigen::Vector3d eye =
      middle + distance * Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth),
                                          std::cos(elevation) * std::sin(azimuth),
                                          std::sin(elevation));
  const double fov =
      2 * std::atan(0.5 * options.width * Pool().ball.radius / (distance * radius_px));
  return camera::CameraModel::LookingAt(eye, middle, options.width, options.height, fov);
}

render::RenderOptions DrawLight(std::uint64_t seed, table::SeededUniform* u) {
  render::RenderOptions o;
  const double warmth = u->Next(), strength = u->Between(kMinStrength, kMaxStrength);
  const auto tint = [&] { return 1 + u->Between(-kTint, kTint); };
  o.light_colour = cv::Vec3f(float(strength * (1 - (1 - kTungstenBlue) * warmth) * tint()),
                             float(strength * (1 - (1 - kTungstenGreen) * warmth) * tint()),
                             float(strength));
  const double tilt = u->Between(0, kMaxLightTilt), towards = u->Between(0, 2 * M_PI);
  o.light_direction = {std::sin(tilt) * std::cos(towards), std::sin(tilt) * std::sin(towards),
                       std::cos(tilt)};
  o.ambient = u->Between(0.2, 0.5);
  o.specular = u->Between(0.2, 0.7);
  o.shininess = u->Between(20, 100);
  cv::Mat hsv(1, 1, CV_8UC3, cv::Scalar(u->Between(0, 180), u->Between(40, 230), u->Between(40, 160)));
  cv::Mat bgr;
  cv::cvtColor(hsv, bgr, cv::COLOR_HSV2BGR);
  o.cloth = bgr.at<cv::Vec3b>(0, 0);
  o.cushion = o.cloth * 0.8;
  o.noise_sigma = u->Between(kMinNoise, kMaxNoise);
  o.seed = seed;
  return o;
}

// Whether a ball at `xy` is in the camera's view, kEdgeRadii of its radius inside the frame.
bool InView(const camera::CameraModel& camera, const Eigen::Vector2d& xy) {
  const double r = Pool().ball.radius;
  const Eigen::Vector3d centre(xy.x(), xy.y(), r);
  if ((camera.rotation * centre + camera.translation).z() <= 0) return false;
  const Eigen::Vector2d p = camera.Project(centre);
  const double margin = kEdgeRadii * camera.fx * r / (camera.Centre() - centre).norm();
  return p.x() > margin && p.y() > margin && p.x() < camera.width - margin &&
         p.y() < camera.height - margin;
}

// The rack's balls placed where the camera sees them, as many as fit.
std::vector<std::pair<BallClass, Eigen::Vector2d>> Place(BallSet set,
                                                         const camera::CameraModel& camera,
                                                         table::SeededUniform* u) {
  static const table::TableGeometry table =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const double r = Pool().ball.radius;
  std::vector<BallClass> rack = RackOf(set);
  if (u->Next() < kCueLeftOut) rack.erase(rack.begin());
  std::vector<table::SceneBall> placed;
  std::vector<std::pair<BallClass, Eigen::Vector2d>> balls;
  for (const BallClass c : rack) {
    for (int t = 0; t < kPlacementTries; ++t) {
      const Eigen::Vector2d p(u->Between(0, table.length), u->Between(0, table.width));
      if (!InView(camera, p) || !table::FreePlace(table, r, placed, p, kClearance)) continue;
      table::SceneBall scene_ball;
      scene_ball.state.head<2>() = p;
      placed.push_back(scene_ball);
      balls.push_back({c, p});
      break;
    }
  }
  return balls;
}

// The frame as the camera gives it: its colours turned, blurred, through JPEG.
cv::Mat ThroughCamera(const cv::Mat& rendered, table::SeededUniform* u) {
  const double turn = u->Between(-kMaxHueTurn, kMaxHueTurn);
  const double c = std::cos(turn), s = std::sin(turn), k = (1 - c) / 3, q = s / std::sqrt(3.0);
  const cv::Matx33f hue_turn(c + k, k - q, k + q, k + q, c + k, k - q, k - q, k + q, c + k);
  cv::Mat seen;
  cv::transform(rendered, seen, hue_turn);
  const double blur = u->Between(0, kMaxBlurPx);
  if (blur > 0.3) cv::GaussianBlur(seen, seen, cv::Size(), blur);
  std::vector<std::uint8_t> jpeg;
  cv::imencode(".jpg", seen, jpeg,
               {cv::IMWRITE_JPEG_QUALITY,
                static_cast<int>(u->Between(kMinJpegQuality, kMaxJpegQuality + 1))});
  return cv::imdecode(jpeg, cv::IMREAD_COLOR);
}

// A detector's outline of the ball at `xy`: its projection, perturbed.
estimator::BallDetection Outline(const camera::CameraModel& camera, const Eigen::Vector2d& xy,
                                 table::SeededUniform* u) {
  const double r = Pool().ball.radius;
  const Eigen::Vector3d centre(xy.x(), xy.y(), r);
  const double radius_px = camera.fx * r / (camera.Centre() - centre).norm();
  estimator::BallDetection ball;
  const double angle = u->Between(0, 2 * M_PI), off = u->Between(0, kCentreJitter) * radius_px;
  ball.pixel = camera.Project(centre) + off * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  ball.radius_px = radius_px * u->Between(kMinRadiusScale, kMaxRadiusScale);
  ball.score = 1;
  return ball;
}

// A frame's seed from the run's, its set and its index (splitmix64's mixing).
std::uint64_t FrameSeed(std::uint64_t seed, BallSet set, int index) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + (static_cast<std::uint64_t>(set) << 32) +
                    static_cast<std::uint64_t>(index);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

RenderedIdentityFrame RenderIdentityFrame(BallSet set, std::uint64_t seed, int index,
                                          const IdentityTrainingOptions& options) {
  const std::uint64_t frame_seed = FrameSeed(seed, set, index);
  table::SeededUniform u(frame_seed);
  const camera::CameraModel camera = DrawCamera(options, &u);
  const render::TableRenderer renderer(camera, Pool(), DrawLight(frame_seed, &u));
  RenderedIdentityFrame frame;
  frame.set = set;
  std::vector<render::RenderBall> balls;
  for (const auto& [ball_class, xy] : Place(set, camera, &u)) {
    balls.push_back(TurnedBall(ball_class, set, xy, &u));
    frame.classes.push_back(ball_class);
    frame.balls.push_back(Outline(camera, xy, &u));
  }
  frame.bgr = ThroughCamera(renderer.Render(balls, 0.0), &u);
  return frame;
}

std::vector<estimator::IdentitySample> RenderedIdentitySamples(
    const IdentityTrainingOptions& options) {
  std::vector<estimator::IdentitySample> samples;
  const int pool_classes = static_cast<int>(estimator::ClassesIn(BallSet::kPool).size());
  for (const BallSet set :
       {BallSet::kPool, BallSet::kSnooker, BallSet::kCarom, BallSet::kBlackball}) {
    const int classes = static_cast<int>(estimator::ClassesIn(set).size());
    const int frames = std::max(1, options.frames_per_set * classes / pool_classes);
    for (int i = 0; i < frames; ++i) {
      const RenderedIdentityFrame frame = RenderIdentityFrame(set, options.seed, i, options);
      const auto looks = estimator::LookAtBalls(frame.bgr, frame.balls, set);
      for (std::size_t b = 0; b < looks.size(); ++b) {
        if (looks[b].seen) samples.push_back({set, frame.classes[b], looks[b].features});
      }
    }
  }
  return samples;
}

}  // namespace billiard::bench
