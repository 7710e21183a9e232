// The plumb-line lens estimate against its truth: straight lines bent by a known k1 (analytic),
// and the renderer's camera with OpenCV's barrel distortion, whose k1 and the table's curved sides
// are known; a pinhole keeps k1 = 0 and a frame without a table stays without one.
#include "estimator/lens_estimate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "estimator/table_finder.h"
#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

// A lens at the frame's centre with the estimate's focal length.
RadialLens Lens(double k1) {
  RadialLens lens;
  lens.k1 = k1;
  lens.focal_px = kLensFocalWidths * kWidth;
  lens.centre = Eigen::Vector2d(0.5 * (kWidth - 1), 0.5 * (kHeight - 1));
  return lens;
}

// The sides of a rectangle 1100 x 560 px about the frame's centre (a table filling it), sampled
// every 2 px along their middle three quarters, through `lens`.
std::array<std::vector<Eigen::Vector2d>, 4> BentRectangle(const RadialLens& lens) {
  const Eigen::Vector2d c = lens.centre;
  const std::array<Eigen::Vector2d, 4> corners = {
      c + Eigen::Vector2d(-550, -280), c + Eigen::Vector2d(550, -280),
      c + Eigen::Vector2d(550, 280), c + Eigen::Vector2d(-550, 280)};
  std::array<std::vector<Eigen::Vector2d>, 4> sides;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = corners[i], b = corners[(i + 1) % 4];
    const int steps = static_cast<int>((b - a).norm() / 2);
    for (int s = 0; s <= steps; ++s) {
      const double t = 0.125 + 0.75 * s / steps;
      sides[i].push_back(lens.ToImage(a + t * (b - a)));
    }
  }
  return sides;
}

TEST(LensEstimate, ThePinholeMapsAreInverseAndTheIdentityWithoutALens) {
  const Eigen::Vector2d p(1000.3, 77.9);
  EXPECT_EQ(Lens(0).ToPinhole(p), p);
  EXPECT_EQ(Lens(0).ToImage(p), p);
  for (const double k1 : {-0.3, 0.2}) {
    const RadialLens lens = Lens(k1);
    EXPECT_LT((lens.ToImage(lens.ToPinhole(p)) - p).norm(), 1e-6) << k1;
    // Barrel distortion draws a pinhole point towards the centre, pincushion away from it.
    const double inward = (lens.ToImage(p) - lens.centre).norm() - (p - lens.centre).norm();
    EXPECT_EQ(inward < 0, k1 < 0) << k1;
  }
}

// Straight lines bent by k1 (no noise): the estimate finds it to the golden section's precision.
TEST(LensEstimate, RecoversTheK1ThatBentStraightLines) {
  for (const double k1 : {-0.3, -0.15, 0.2}) {
    const LensEstimate estimate = EstimateRadialLens(BentRectangle(Lens(k1)), {kWidth, kHeight}, 1);
    EXPECT_NEAR(estimate.lens.k1, k1, 1e-3);
    EXPECT_LT(estimate.best_rms_px, 0.01);
    EXPECT_GT(estimate.pinhole_rms_px, 1.0);
  }
  // Straight lines traced on a pixel grid: rounding is not a bend.
  auto sides = BentRectangle(Lens(0));
  for (auto& side : sides) {
    for (auto& p : side) p = p.array().round();
  }
  EXPECT_TRUE(EstimateRadialLens(sides, {kWidth, kHeight}, 1).lens.IsPinhole());
}

// A table seen from 20 degrees above its cloth, as the hard suite's camera sees it: the far side
// 64 px above the frame's centre and 600 px long, the near one 88 px below and 1140 px long, the
// sides traced every 4 px (the search's pixels). Each short side's outline turns the corner onto
// the near side for its last fifth (found so over a rack), the long sides are straight. A strong
// barrel makes each L nearly a line and lowers the four sides' residual as much as
// a lens must, but it bends the straight sides: no lens.
TEST(LensEstimate, ASideTurningACornerIsNoLens) {
  const Eigen::Vector2d c = Lens(0).centre;
  const std::array<Eigen::Vector2d, 4> corners = {
      c + Eigen::Vector2d(-570, 88), c + Eigen::Vector2d(-300, -64),
      c + Eigen::Vector2d(300, -64), c + Eigen::Vector2d(570, 88)};
  constexpr double kStepPx = 4.0, kTurnStartPx = 40.0;
  std::array<std::vector<Eigen::Vector2d>, 4> sides;
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector2d a = corners[i], b = corners[(i + 1) % 4];
    const int steps = static_cast<int>((b - a).norm() / kStepPx);
    for (int s = 0; s <= steps; ++s) {
      sides[i].push_back((a + (0.125 + 0.75 * s / steps) * (b - a)).array().round());
    }
  }
  const std::size_t turned = sides[0].size() / 4;
  for (std::size_t j = 1; j <= turned; ++j) {
    sides[0].insert(sides[0].begin(), corners[0] + Eigen::Vector2d(kTurnStartPx + kStepPx * j, 0));
    sides[2].push_back(corners[3] - Eigen::Vector2d(kTurnStartPx + kStepPx * j, 0));
  }
  const LensEstimate estimate = EstimateRadialLens(sides, {kWidth, kHeight}, kStepPx);
  std::fprintf(stderr, "pinhole %.3f px, best k1 %.3f at %.3f px\n", estimate.pinhole_rms_px,
               estimate.best_k1, estimate.best_rms_px);
  const double grid = kGridNoise * kStepPx;
  const auto excess = [&](double rms) { return std::sqrt(std::max(0.0, rms * rms - grid * grid)); };
  EXPECT_LT(excess(estimate.best_rms_px), kLensGain * excess(estimate.pinhole_rms_px));
  EXPECT_TRUE(estimate.lens.IsPinhole());
}

cv::Mat Render(const camera::CameraModel& camera) {
  render::RenderOptions options;
  options.exposure_s = 0;
  const render::TableRenderer renderer(camera, Pool(), options);
  return renderer.Render({render::RenderBall::AtRest(0, render::PoolBallColour(0), {0.6, 0.6}),
                          render::RenderBall::AtRest(3, render::PoolBallColour(3), {1.8, 0.4})},
                         0.0);
}

// An overhead camera with the lens, the table spanning `fill` of the frame's width through a
// pinhole (k1 = -0.3 with 1.05: the hard suite's lens camera, bench/hard_suite.h, the lens pulling
// the table's ends into the frame).
camera::CameraModel LensCamera(double k1, double fill = 0.92) {
  constexpr double kHeightAboveCloth = 2.5;
  return camera::CameraModel::Overhead(Pool().table, kWidth, kHeight, kHeightAboveCloth, fill,
                                       {k1, 0, 0, 0, 0});
}

// The largest distance [px] of the playing surface's true edge (on the cloth, which an overhead
// camera sees every cushion's face meet), projected through the camera's lens, from the side
// found along it, where it is in the frame.
double WorstSidePx(const TableRegion& table, const camera::CameraModel& camera) {
  const physics::TableParameters& t = Pool().table;
  const std::array<Eigen::Vector3d, 4> corners = {
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(t.length, 0, 0),
      Eigen::Vector3d(t.length, t.width, 0), Eigen::Vector3d(0, t.width, 0)};
  constexpr int kSamples = 40;
  double worst_side = 0;
  for (int i = 0; i < 4; ++i) {
    double best = HUGE_VAL;
    for (int j = 0; j < 4; ++j) {
      double worst = 0;
      for (int s = 0; s <= kSamples; ++s) {
        const Eigen::Vector3d p = corners[i] + (corners[(i + 1) % 4] - corners[i]) * s / kSamples;
        const Eigen::Vector2d pixel = camera.Project(p);
        if (cv::Rect(0, 0, kWidth, kHeight).contains(cv::Point(pixel.x(), pixel.y()))) {
          worst = std::max(worst, table.DistanceToSide(j, pixel));
        }
      }
      best = std::min(best, worst);
    }
    worst_side = std::max(worst_side, best);
  }
  return worst_side;
}

// The acceptance of issue 45's lens case: every side within 3 px under k1 = -0.3. The camera's
// k1 is seen as k1 (width / fx)^2 at the estimate's focal length of one width; recovered within
// kK1Tolerance of it (the outline is traced at a quarter of the resolution, and the cloth's edge
// it follows is the cushions' foot, not a painted line).
TEST(LensEstimate, FindsTheTableThroughABarrelLens) {
  constexpr double kSideTolerancePx = 3.0, kK1Tolerance = 0.1;
  for (const auto& [k1, fill] : {std::pair{-0.3, 1.05}, std::pair{-0.15, 0.92}}) {
    const camera::CameraModel camera = LensCamera(k1, fill);
    const TableSearch search = FindTable(Render(camera));
    ASSERT_TRUE(search.table) << k1 << ": " << search.reason;
    const double seen = k1 * std::pow(kWidth / camera.fx, 2);
    EXPECT_NEAR(search.table->lens.k1, seen, kK1Tolerance * std::abs(seen)) << k1;
    EXPECT_LT(WorstSidePx(*search.table, camera), kSideTolerancePx) << k1;
    // The ball at (0.6, 0.6) m is there on the table (the homography is the pinhole's).
    const Eigen::Vector2d ball = camera.Project({0.6, 0.6, Pool().ball.radius});
    EXPECT_TRUE(search.table->Contains(ball, 10.0)) << k1;
  }
}

// A pinhole frame keeps k1 = 0, overhead and oblique.
TEST(LensEstimate, APinholeFrameHasNoLens) {
  const physics::TableParameters& table = Pool().table;
  const Eigen::Vector3d middle(0.5 * table.length, 0.5 * table.width, 0.0);
  for (const camera::CameraModel& camera :
       {LensCamera(0.0), camera::CameraModel::Overhead(table, kWidth, kHeight),
        camera::CameraModel::LookingAt(middle + Eigen::Vector3d(0, -2.3, 1.6), middle, kWidth,
                                       kHeight, 1.2)}) {
    const TableSearch search = FindTable(Render(camera));
    ASSERT_TRUE(search.table) << search.reason;
    EXPECT_TRUE(search.table->lens.IsPinhole()) << search.table->lens.k1;
  }
}

// What is not a table stays not one: a round cloth-coloured mat on a dark floor.
TEST(LensEstimate, AFrameWithoutATableStaysWithoutOne) {
  cv::Mat mat(kHeight, kWidth, CV_8UC3, cv::Scalar(30, 30, 30));
  cv::circle(mat, {kWidth / 2, kHeight / 2}, 300, cv::Scalar(60, 110, 30), cv::FILLED);
  EXPECT_FALSE(FindTable(mat).table);
}

}  // namespace
}  // namespace billiard::estimator
