// The balls of a table mostly out of the frame, found on its cloth (table_fallback.h's
// ClothWithBalls), on rendered frames whose camera is the truth: the overhead camera moved along
// the table until 55, 65 and 75 % of its length is out of the frame, and across it until a long
// side and 60 % of its width are. No table is found in any (less than half of its length seen
// leaves a strip of cloth as much as an end, table_partial.h; a long side out leaves the
// proportions unknown), and the floor beside the table is the frame's likeliest colour and a
// straight-sided region: the balls must be looked for on the cloth, not on it.
#include "estimator/table_fallback.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "estimator/ball_detector.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
// A found ball is one of the table's when its centre is within kMatchRadii of a ball's radius of
// that ball's image centre; the detector's centres of whole balls are within kCentrePx.
constexpr double kMatchRadii = 1.0, kCentrePx = 1.5;
// The share of a frame's edge the cloth's region reaches is the playing surface's within this:
// the cushions' tops are of the cloth (2 x 5 cm on a 1.27 m wide bed: 0.08 of it).
constexpr double kEdgeShareTolerance = 0.1;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

double Radius() { return Pool().ball.radius; }

// Balls on a grid over the whole table, 4 across and 8 along, every one apart from its neighbours.
const std::vector<Eigen::Vector2d>& Layout() {
  constexpr int kAlong = 8, kAcross = 4;
  static const std::vector<Eigen::Vector2d> balls = [] {
    const physics::TableParameters& t = Pool().table;
    std::vector<Eigen::Vector2d> grid;
    for (int i = 0; i < kAlong; ++i) {
      for (int j = 0; j < kAcross; ++j) {
        // Every other row a quarter step along: no two balls in a line across the table.
        const double x = (i + 0.25 + 0.5 * (j % 2)) * t.length / kAlong;
        grid.emplace_back(x, (j + 0.5) * t.width / kAcross);
      }
    }
    return grid;
  }();
  return balls;
}

// The share of the segment from `a` to `b` on the cloth whose image is in the frame.
double SeenShare(const camera::CameraModel& c, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  constexpr int kSamples = 200;
  int seen = 0;
  for (int i = 0; i < kSamples; ++i) {
    const Eigen::Vector2d p = c.Project(a + (i + 0.5) / kSamples * (b - a));
    seen += p.x() >= 0 && p.y() >= 0 && p.x() <= kWidth - 1 && p.y() <= kHeight - 1;
  }
  return static_cast<double>(seen) / kSamples;
}

// The overhead camera moved along `direction` until `share_out` of the table's extent that way
// (through its middle) is out of the frame (bisection on the distance moved).
camera::CameraModel MovedOut(const Eigen::Vector3d& direction, double share_out) {
  const camera::CameraModel overhead = camera::CameraModel::Overhead(Pool().table, kWidth, kHeight);
  const Eigen::Vector3d middle(0.5 * Pool().table.length, 0.5 * Pool().table.width, 0.0);
  const double extent =
      std::abs(direction.dot(Eigen::Vector3d(Pool().table.length, Pool().table.width, 0.0)));
  const auto moved = [&](double d) {
    camera::CameraModel c = overhead;
    c.translation = -c.rotation * (c.Centre() + d * direction);
    return c;
  };
  double low = 0, high = extent;
  for (int i = 0; i < 40; ++i) {
    const double d = 0.5 * (low + high);
    const camera::CameraModel c = moved(d);
    const double out =
        1 - SeenShare(c, middle - 0.5 * extent * direction, middle + 0.5 * extent * direction);
    (out < share_out ? low : high) = d;
  }
  return moved(0.5 * (low + high));
}

// The share of each edge of the frame (kFrameEdges) that sees the playing surface.
std::array<double, 4> SurfaceAtFrameEdges(const camera::CameraModel& c) {
  constexpr int kSamples = 400;
  const Eigen::Vector2d last(kWidth - 1, kHeight - 1);
  const std::array<std::pair<Eigen::Vector2d, Eigen::Vector2d>, 4> edges = {
      {{{0, 0}, {0, last.y()}},
       {{0, 0}, {last.x(), 0}},
       {{last.x(), 0}, last},
       {{0, last.y()}, last}}};
  std::array<double, 4> shares;
  for (int i = 0; i < 4; ++i) {
    int on = 0;
    for (int k = 0; k < kSamples; ++k) {
      const double t = (k + 0.5) / kSamples;
      const Eigen::Vector3d p = c.Unproject((1 - t) * edges[i].first + t * edges[i].second, 0.0);
      on += p.x() >= 0 && p.y() >= 0 && p.x() <= Pool().table.length && p.y() <= Pool().table.width;
    }
    shares[i] = static_cast<double>(on) / kSamples;
  }
  return shares;
}

struct Scene {
  std::string name;
  camera::CameraModel camera;
};

std::vector<Scene> MostlyOutOfFrame() {
  const Eigen::Vector3d along = Eigen::Vector3d::UnitX(), across = Eigen::Vector3d::UnitY();
  return {{"55 % of the length out", MovedOut(along, 0.55)},
          {"65 % of the length out", MovedOut(along, 0.65)},
          {"75 % of the length out", MovedOut(-along, 0.75)},
          {"a long side and 60 % of the width out", MovedOut(across, 0.60)}};
}

cv::Mat Render(const camera::CameraModel& camera, const cv::Vec3b& cloth) {
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < Layout().size(); ++i) {
    const int id = static_cast<int>(i % 16);
    balls.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id), Layout()[i]));
  }
  render::RenderOptions options;
  options.exposure_s = 0;
  options.cloth = cloth;
  options.cushion = cloth * 0.8;
  return render::TableRenderer(camera, Pool(), options).Render(balls, 0.0);
}

TEST(TableFallback, TheBallsOfATableMostlyOutOfTheFrameAreFoundOnItsCloth) {
  for (const cv::Vec3b& cloth : {cv::Vec3b(40, 120, 30), cv::Vec3b(140, 70, 20)}) {
    for (const Scene& scene : MostlyOutOfFrame()) {
      const std::string name = scene.name + " (cloth " + std::to_string(cloth[0]) + ")";
      const cv::Mat frame = Render(scene.camera, cloth);
      ASSERT_FALSE(FindTable(frame).table) << name << ": a table is found; the case is another";
      BallDetector detector;
      const std::vector<BallDetection> found = detector.Detect(frame);
      ASSERT_TRUE(detector.table()) << name;
      EXPECT_FALSE(detector.knows_table()) << name;
      const std::array<double, 4> seen = ClothAtFrameEdges(*detector.table());
      const std::array<double, 4> truth = SurfaceAtFrameEdges(scene.camera);
      for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(seen[i], truth[i], kEdgeShareTolerance) << name << ", " << kFrameEdges[i];
      }
      const double radius_px = ExpectedRadiusPx(scene.camera, Radius());
      int whole = 0;
      for (const Eigen::Vector2d& p : Layout()) {
        const Eigen::Vector2d pixel = scene.camera.Project({p.x(), p.y(), Radius()});
        const bool in_view = pixel.x() > radius_px && pixel.x() < kWidth - 1 - radius_px &&
                             pixel.y() > radius_px && pixel.y() < kHeight - 1 - radius_px;
        if (!in_view) continue;
        ++whole;
        EXPECT_TRUE(std::any_of(
            found.begin(), found.end(),
            [&](const BallDetection& b) { return (b.pixel - pixel).norm() < kCentrePx; }))
            << name << ": the ball at " << p.transpose() << " (pixel " << pixel.transpose() << ")";
      }
      EXPECT_GE(whole, 4) << name;
      for (const BallDetection& b : found) {
        EXPECT_TRUE(std::any_of(
            Layout().begin(), Layout().end(),
            [&](const Eigen::Vector2d& p) {
              const Eigen::Vector2d pixel = scene.camera.Project({p.x(), p.y(), Radius()});
              return (b.pixel - pixel).norm() < kMatchRadii * radius_px;
            }))
            << name << ": no ball at " << b.pixel.transpose();
      }
    }
  }
}

}  // namespace
}  // namespace billiard::estimator
