#include "bench/hard_suite.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "bench/detection_suite.h"
#include "sim/camera/camera_model.h"
#include "sim/render/occluders.h"
#include "sim/render/table_renderer.h"

namespace billiard::bench {

namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr double kOverheadHeight = 2.5, kOverheadFill = 0.92;  // as the synthetic suite's
// The lens case: barrel distortion k1 = -0.3 pulls the table in, so it fills more of the frame.
constexpr double kBarrelK1 = -0.3, kLensFill = 1.05;
// A third of the table out of the frame: at one end, and across it with the camera turned.
constexpr double kShareOut = 1.0 / 3.0;
constexpr double kAcrossShift = 0.45, kTurnDegrees = 12.0;  // of the table's width
// The elevation cases: a camera of this horizontal field of view [rad], stepped back from the
// table's middle until the table's corners are this far inside the frame [share of the frame].
constexpr double kObliqueFov = 1.0, kFrameMargin = 0.03, kStepBack = 0.05;
constexpr double kElevations[] = {15, 20, 30, 45};
// A ball less than this share seen is hidden: its label ignored.
constexpr double kLeastSeenShare = 0.5;
// The side's points sampled along it for its truth, and the surface's, for the share in the frame.
constexpr int kSideSamples = 400, kSurfaceSamples = 60;
constexpr double kSideTolerancePx = 2.0, kLensSideTolerancePx = 3.0;
constexpr double kOccluderNoise = 2.0;  // gray levels, the renderer's sensor noise

const cv::Vec3b kSkin{120, 160, 215}, kCueWood{70, 135, 190}, kShirt{45, 38, 36},
    kHair{25, 28, 32}, kSleeve{60, 50, 48};

struct Case {
  std::string condition;
  camera::CameraModel camera;
  bool overhead = true;
  // The occluders of a scene, from a place along the table [m].
  std::function<std::vector<render::Capsule>(double x)> occluders;
  double tolerance_px = kSideTolerancePx;
};

camera::CameraModel Overhead(const physics::TableParameters& table, double fill = kOverheadFill,
                             double k1 = 0.0) {
  return camera::CameraModel::Overhead(table, kWidth, kHeight, kOverheadHeight, fill,
                                       {k1, 0.0, 0.0, 0.0, 0.0});
}

// The camera moved by `shift` (table frame) and turned by `turn` about its optical axis.
camera::CameraModel Moved(camera::CameraModel c, const Eigen::Vector3d& shift, double turn) {
  const Eigen::Vector3d centre = c.Centre() + shift;
  c.rotation = Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ()).toRotationMatrix() * c.rotation;
  c.translation = -c.rotation * centre;
  return c;
}

// How far to move an overhead camera along a table `extent` long that spans `extent_px` of a frame
// `frame_px` wide for `share` of it to leave the frame: the share, and the margin beyond the table.
double ShiftForShareOut(double extent, double extent_px, double frame_px, double share) {
  return share * extent + 0.5 * (frame_px - extent_px) * extent / extent_px;
}

bool InFrame(const camera::CameraModel& c, const Eigen::Vector2d& p, double margin = 0.0) {
  return p.x() >= margin * c.width && p.y() >= margin * c.height &&
         p.x() < (1 - margin) * c.width && p.y() < (1 - margin) * c.height;
}

// A camera beside the long side y = 0, `elevation_deg` above the table's middle, stepped back
// until the table is in its frame.
camera::CameraModel Elevated(const physics::TableParameters& table, double elevation_deg) {
  const Eigen::Vector3d middle(0.5 * table.length, 0.5 * table.width, 0.0);
  const double e = elevation_deg * M_PI / 180.0;
  const Eigen::Vector3d back(0.0, -std::cos(e), std::sin(e));
  for (double d = 1.0;; d += kStepBack) {
    const camera::CameraModel c =
        camera::CameraModel::LookingAt(middle + d * back, middle, kWidth, kHeight, kObliqueFov);
    bool all_in = true;
    for (const double x : {0.0, table.length}) {
      for (const double y : {0.0, table.width}) {
        all_in = all_in && InFrame(c, c.Project({x, y, 0.0}), kFrameMargin);
      }
    }
    if (all_in) return c;
  }
}

// An arm reaching in over the long side y = 0 at `x`, its hand, and the cue under it.
std::vector<render::Capsule> Arm(double x) {
  const Eigen::Vector3d elbow(x, -0.30, 0.35), wrist(x + 0.10, 0.18, 0.10);
  return {{elbow, wrist, 0.050, 0.032, kSkin},
          {wrist, Eigen::Vector3d(x + 0.16, 0.27, 0.07), 0.038, 0.042, kSkin},
          {Eigen::Vector3d(x - 0.55, -0.85, 0.42), Eigen::Vector3d(x + 0.30, 0.42, 0.06), 0.015,
           0.006, kCueWood}};
}

// A player leaning over the long side y = 0 at `x`: torso, shoulders, head, one arm reaching in.
std::vector<render::Capsule> Player(double x) {
  const Eigen::Vector3d shoulder(x + 0.2, 0.0, 0.55), wrist(x + 0.32, 0.42, 0.12);
  return {{Eigen::Vector3d(x, -0.55, 0.80), Eigen::Vector3d(x, -0.08, 0.56), 0.18, 0.17, kShirt},
          {Eigen::Vector3d(x - 0.22, -0.02, 0.55), shoulder, 0.10, 0.10, kShirt},
          {Eigen::Vector3d(x, 0.14, 0.52), Eigen::Vector3d(x, 0.16, 0.52), 0.10, 0.10, kHair},
          {shoulder, wrist, 0.055, 0.034, kSleeve},
          {wrist, Eigen::Vector3d(x + 0.36, 0.52, 0.08), 0.038, 0.042, kSkin}};
}

std::vector<Case> Cases(const physics::TableParameters& table) {
  const camera::CameraModel overhead = Overhead(table);
  const double length_px = overhead.fx * table.length / kOverheadHeight;
  std::vector<Case> cases = {
      {"arm", overhead, true, Arm},
      {"player", overhead, true, Player},
      {"out-of-frame end",
       Moved(overhead,
             {ShiftForShareOut(table.length, length_px, kWidth, kShareOut), 0.0, 0.0}, 0.0),
       true, nullptr},
      {"out-of-frame turned",
       Moved(overhead, {0.0, kAcrossShift * table.width, 0.0}, kTurnDegrees * M_PI / 180.0), true,
       nullptr},
      {"lens k1=-0.3", Overhead(table, kLensFill, kBarrelK1), true, nullptr,
       kLensSideTolerancePx}};
  for (const double e : kElevations) {
    cases.push_back({"elevation " + std::to_string(static_cast<int>(e)), Elevated(table, e), false,
                     nullptr});
  }
  return cases;
}

// Each side's edge in the frame, sampled: where the cushion's face meets the cloth when the camera
// is on the playing surface's side of the cushion (it sees the face), the nose's line when it is
// beyond it (the cushion hides its face and the cloth at its foot): table_pose.h's convention.
std::array<std::vector<Eigen::Vector2d>, 4> TrueSides(const camera::CameraModel& c,
                                                      const physics::TableParameters& table,
                                                      double nose_height) {
  const std::array<Eigen::Vector3d, 4> corners = {
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(table.length, 0, 0),
      Eigen::Vector3d(table.length, table.width, 0), Eigen::Vector3d(0, table.width, 0)};
  const Eigen::Vector3d middle(0.5 * table.length, 0.5 * table.width, 0.0);
  std::array<std::vector<Eigen::Vector2d>, 4> sides;
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3d& a = corners[k];
    const Eigen::Vector3d& b = corners[(k + 1) % 4];
    const Eigen::Vector3d along = (b - a).normalized();
    Eigen::Vector3d inward = middle - a;
    inward -= inward.dot(along) * along;
    const bool sees_face = (c.Centre() - a).dot(inward) > 0;
    const Eigen::Vector3d up(0.0, 0.0, sees_face ? 0.0 : nose_height);
    for (int i = 0; i <= kSideSamples; ++i) {
      const double t = static_cast<double>(i) / kSideSamples;
      const Eigen::Vector2d p = c.Project(a + up + t * (b - a));
      if (InFrame(c, p)) sides[k].push_back(p);
    }
  }
  return sides;
}

double SeenShare(const camera::CameraModel& c, const physics::TableParameters& table) {
  int seen = 0, all = 0;
  for (int i = 0; i < 2 * kSurfaceSamples; ++i) {
    for (int j = 0; j < kSurfaceSamples; ++j) {
      const Eigen::Vector3d p((i + 0.5) * table.length / (2 * kSurfaceSamples),
                              (j + 0.5) * table.width / kSurfaceSamples, 0.0);
      seen += InFrame(c, c.Project(p));
      ++all;
    }
  }
  return static_cast<double>(seen) / all;
}

// The occluders drawn into the frame (with the renderer's sensor noise on them), and which balls
// are then hidden.
std::vector<bool> Occlude(const Case& c, const render::RenderOptions& options,
                          const std::vector<Eigen::Vector2d>& balls, double r, double x,
                          cv::Mat* image) {
  std::vector<render::OccludedBall> spheres;
  for (const auto& b : balls) spheres.push_back({Eigen::Vector3d(b.x(), b.y(), r), r});
  cv::Mat mask = cv::Mat::zeros(image->size(), CV_8UC1);
  if (c.occluders) {
    mask = render::DrawOccluders(c.camera, c.occluders(x), spheres, options.light_direction,
                                 options.ambient, image);
    cv::Mat noise(image->size(), CV_16SC3);
    cv::RNG(options.seed).fill(noise, cv::RNG::NORMAL, 0.0, kOccluderNoise);
    cv::Mat noisy;
    cv::add(*image, noise, noisy, mask > 0, CV_8UC3);
    noisy.copyTo(*image, mask > 0);
  }
  std::vector<bool> hidden;
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    hidden.push_back(render::VisibleShare(c.camera, spheres, i, mask) < kLeastSeenShare);
  }
  return hidden;
}

}  // namespace

std::vector<HardFrame> RenderHardSuite(const physics::ModelParameters& params, std::uint32_t seed,
                                       const std::string& only_case) {
  const double r = params.ball.radius;
  const std::vector<SuiteCloth> cloths = {SuiteCloths()[0], SuiteCloths()[1], SuiteCloths()[3]};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> along(0.3 * params.table.length,
                                               0.6 * params.table.length);
  std::vector<HardFrame> frames;
  int scene = 0;
  for (const Case& c : Cases(params.table)) {
    for (const SuiteCloth& cloth : cloths) {
      for (const bool rack : {false, true}) {
        const std::vector<Eigen::Vector2d> balls = SceneBalls(params, rack, seed + scene, &rng);
        if (!only_case.empty() && c.condition.rfind(only_case, 0) != 0) {
          along(rng);  // as when rendered: the cases kept are the whole suite's frames
          ++scene;
          continue;
        }
        const render::RenderOptions options = SuiteRenderOptions(cloth, seed + scene);
        cv::Mat image = render::TableRenderer(c.camera, params, options).Render(PoolBalls(balls), 0);
        const std::vector<bool> hidden = Occlude(c, options, balls, r, along(rng), &image);
        std::string slug = c.condition + "-" + cloth.name + (rack ? "-rack" : "-scattered");
        std::replace(slug.begin(), slug.end(), ' ', '-');
        HardFrame frame;
        frame.frame = LabelBalls(slug, c.camera, c.overhead, balls, r, hidden);
        frame.frame.source = "billiard bench-detect --hard-suite (sim/render): " + c.condition;
        frame.frame.image = image;
        frame.condition = c.condition;
        frame.sides = TrueSides(c.camera, params.table, options.cushion_height);
        frame.seen_share = SeenShare(c.camera, params.table);
        frame.tolerance_px = c.tolerance_px;
        frames.push_back(std::move(frame));
        ++scene;
      }
    }
  }
  return frames;
}

std::array<double, 4> SideErrorsPx(const HardFrame& truth, const estimator::TableRegion& table) {
  std::array<double, 4> errors{-1, -1, -1, -1};
  for (int k = 0; k < 4; ++k) {
    if (truth.sides[k].empty()) continue;
    double best = HUGE_VAL;
    for (int j = 0; j < 4; ++j) {
      double worst = 0;
      for (const auto& p : truth.sides[k]) worst = std::max(worst, table.DistanceToSide(j, p));
      best = std::min(best, worst);
    }
    errors[k] = best;
  }
  return errors;
}

}  // namespace billiard::bench
