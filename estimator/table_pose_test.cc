// The table without markers and where it is not found, on rendered frames with known truth: the
// camera's pose from the table's corners (table_pose.h), a calibrated rig's frames read through
// an arm across the table (table_fallback.h's TableSeenBy), the balls on the cloth where no table
// is found (ClothOnly), and a detector that keeps the table it learnt.
#include "estimator/table_pose.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "estimator/ball_detector.h"
#include "estimator/ball_estimator.h"
#include "estimator/table_fallback.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"

namespace billiard::estimator {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

double Radius() { return Pool().ball.radius; }

// The renderer's cushions at the noses' height the calibration assumes.
render::RenderOptions Options(std::uint64_t seed) {
  render::RenderOptions options;
  options.exposure_s = 0;
  options.seed = seed;
  options.cushion_height = NoseHeight(Radius());
  return options;
}

const std::vector<Eigen::Vector2d>& Layout() {
  static const std::vector<Eigen::Vector2d> balls = {
      {0.40, 0.30}, {0.70, 1.00}, {1.00, 0.55}, {1.35, 0.95}, {1.60, 0.25},
      {1.95, 0.70}, {2.25, 0.40}, {2.30, 1.05}, {0.25, 0.90}};
  return balls;
}

cv::Mat Render(const camera::CameraModel& camera, std::uint64_t seed) {
  std::vector<render::RenderBall> balls;
  for (std::size_t i = 0; i < Layout().size(); ++i) {
    const int id = static_cast<int>(i);
    balls.push_back(render::RenderBall::AtRest(id, render::PoolBallColour(id), Layout()[i]));
  }
  return render::TableRenderer(camera, Pool(), Options(seed)).Render(balls, 0.0);
}

// A forearm and a sleeve, dark, across the whole table from the near rail to the far one
// between x0 and x1 [m] on the near side, 12 cm wide: an arm over an overhead rig's table.
void DrawArm(const camera::CameraModel& camera, double x0, double x1, cv::Mat* frame) {
  std::vector<cv::Point> arm;
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(x0, -0.3, 0.1), Eigen::Vector3d(x0 + 0.12, -0.3, 0.1),
        Eigen::Vector3d(x1 + 0.12, 1.6, 0.1), Eigen::Vector3d(x1, 1.6, 0.1)}) {
    const Eigen::Vector2d q = camera.Project(p);
    arm.emplace_back(static_cast<int>(std::lround(q.x())), static_cast<int>(std::lround(q.y())));
  }
  cv::fillConvexPoly(*frame, arm, cv::Scalar(45, 50, 60), cv::LINE_AA);
}

// Whether a table point lies under the arm of DrawArm, with a ball's radius to spare.
bool UnderArm(const Eigen::Vector2d& p, double x0, double x1) {
  const double along = (p.y() + 0.3) / 1.9;
  const double left = x0 + along * (x1 - x0);
  return p.x() > left - 2 * Radius() && p.x() < left + 0.12 + 2 * Radius();
}

// The largest distance [m] on the table, at the balls' height, between where `truth` sees a grid
// of points and where `fitted` maps the pixels back.
double LargestMappingError(const camera::CameraModel& truth, const camera::CameraModel& fitted) {
  double largest = 0;
  for (double x = 0.1; x < Pool().table.length; x += 0.3) {
    for (double y = 0.1; y < Pool().table.width; y += 0.3) {
      const Eigen::Vector3d p(x, y, Radius());
      largest = std::max(largest, (fitted.Unproject(truth.Project(p), Radius()) - p).norm());
    }
  }
  return largest;
}

camera::CameraModel Side() {
  const Eigen::Vector3d middle(0.5 * Pool().table.length, 0.5 * Pool().table.width, 0.0);
  return camera::CameraModel::LookingAt(middle + Eigen::Vector3d(0, -2.3, 1.6), middle, 1280, 720,
                                        1.2);
}

TEST(TablePose, TheCameraFromTheTableFoundWithoutMarkers) {
  const camera::CameraModel overhead = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  for (const auto& [name, truth, bound_m] :
       {std::tuple{"overhead", overhead, 0.002}, std::tuple{"side", Side(), 0.005}}) {
    std::string why;
    const auto corners = FoundTableCorners(Render(truth, 1), &why);
    ASSERT_TRUE(corners) << name << ": " << why;
    const auto fit = CalibrateFromCorners(*corners, {1280, 720}, Pool().table, NoseHeight(Radius()));
    ASSERT_TRUE(fit) << name;
    EXPECT_LT(fit->rms_reprojection_px, 1.0) << name;
    EXPECT_LT(LargestMappingError(truth, fit->camera), bound_m) << name;
  }
}

// A wide-angle lens (barrel distortion k1 = -0.3, the table filling the frame) bends the sides:
// the table finder estimates the lens from the bend (lens_estimate.h), and the pose from the
// corners is fitted through it. A pinhole fitted to the same corners maps the cloth centimetres
// off (the lens moves the corners radially, by some 25 px here).
TEST(TablePose, TheCameraThroughAWideAngleLensFromTheTableFound) {
  constexpr double kBarrelK1 = -0.3, kFill = 1.05, kHeight = 2.5;
  const camera::CameraModel truth = camera::CameraModel::Overhead(
      Pool().table, 1280, 720, kHeight, kFill, {kBarrelK1, 0.0, 0.0, 0.0, 0.0});
  std::string why;
  const auto corners = FoundTableCorners(Render(truth, 1), &why);
  ASSERT_TRUE(corners) << why;
  ASSERT_FALSE(corners->lens.IsPinhole());
  const auto fit = CalibrateFromCorners(*corners, {1280, 720}, Pool().table, NoseHeight(Radius()));
  ASSERT_TRUE(fit);
  EXPECT_LT(fit->rms_reprojection_px, 1.0);
  EXPECT_NEAR(fit->camera.distortion[0] / (fit->camera.fx * fit->camera.fx),
              kBarrelK1 / (truth.fx * truth.fx), 0.1 * std::abs(kBarrelK1) / (truth.fx * truth.fx));
  EXPECT_LT(LargestMappingError(truth, fit->camera), 0.004);

  TableCornerPixels through_a_pinhole = *corners;
  through_a_pinhole.lens = RadialLens{};
  const auto pinhole =
      CalibrateFromCorners(through_a_pinhole, {1280, 720}, Pool().table, NoseHeight(Radius()));
  ASSERT_TRUE(pinhole);
  EXPECT_GT(LargestMappingError(truth, pinhole->camera), 0.02);
}

// The corners of the playing surface as the side camera sees them: the near cushion (y = 0) from
// behind, its nose; the other three their faces, down to the cloth. Each corner is where the image
// lines of its two sides meet.
std::array<Eigen::Vector2d, 4> CornersSeenFromTheSide(const camera::CameraModel& camera) {
  const double z = NoseHeight(Radius()), l = Pool().table.length, w = Pool().table.width;
  const std::array<std::array<Eigen::Vector3d, 2>, 4> sides = {{
      {Eigen::Vector3d(0, 0, z), Eigen::Vector3d(l, 0, z)},
      {Eigen::Vector3d(l, 0, 0), Eigen::Vector3d(l, w, 0)},
      {Eigen::Vector3d(l, w, 0), Eigen::Vector3d(0, w, 0)},
      {Eigen::Vector3d(0, w, 0), Eigen::Vector3d(0, 0, 0)}}};
  std::array<Eigen::Vector3d, 4> lines;
  for (int i = 0; i < 4; ++i) {
    lines[i] = camera.Project(sides[i][0]).homogeneous().cross(
        camera.Project(sides[i][1]).homogeneous());
  }
  std::array<Eigen::Vector2d, 4> corners;
  for (int i = 0; i < 4; ++i) corners[i] = lines[(i + 3) % 4].cross(lines[i]).hnormalized();
  return corners;
}

TEST(TablePose, GivenCornersInAnyOrderGiveTheSameCamera) {
  const camera::CameraModel truth = Side();
  const double z = NoseHeight(Radius());
  const std::array<Eigen::Vector2d, 4> around = CornersSeenFromTheSide(truth);
  // Started at each corner, and run the other way round (the first side then a short one).
  for (int start = 0; start < 4; ++start) {
    for (const bool reversed : {false, true}) {
      TableCornerPixels given;
      for (int i = 0; i < 4; ++i) {
        given.pixels[i] = around[(reversed ? start - i + 8 : start + i) % 4];
      }
      given.first_side_long = (start % 2 == 0) != reversed;
      const auto fit = CalibrateFromCorners(given, {1280, 720}, Pool().table, z);
      ASSERT_TRUE(fit);
      EXPECT_LT(LargestMappingError(truth, fit->camera), 1e-4)
          << "start " << start << (reversed ? " reversed" : "");
      EXPECT_NEAR(fit->camera.fx, truth.fx, 0.02 * truth.fx) << "the focal length fitted";
    }
  }
}

// The arm of the rig's frames: across the table between these x [m] on the near and far rail.
constexpr double kArmFrom = 1.05, kArmTo = 1.45;

// The rig's camera, calibrated from its table found in a frame without the arm.
camera::CameraModel RigCalibration(const camera::CameraModel& truth) {
  std::string why;
  const auto corners = FoundTableCorners(Render(truth, 1), &why);
  EXPECT_TRUE(corners) << why;
  const auto fit = CalibrateFromCorners(*corners, {1280, 720}, Pool().table, NoseHeight(Radius()));
  EXPECT_TRUE(fit);
  return fit ? fit->camera : truth;
}

// Every ball of the layout beside the arm is within 3 mm of one of `found` [m], and nothing else
// is found.
void ExpectTheBallsBesideTheArm(const std::vector<Eigen::Vector2d>& found) {
  int seen = 0;
  for (const Eigen::Vector2d& p : Layout()) {
    if (UnderArm(p, kArmFrom, kArmTo)) continue;
    ++seen;
    double nearest = HUGE_VAL;
    for (const Eigen::Vector2d& f : found) nearest = std::min(nearest, (f - p).norm());
    EXPECT_LT(nearest, 0.003) << "ball at " << p.transpose();
  }
  EXPECT_GE(seen, 7);
  EXPECT_EQ(static_cast<int>(found.size()), seen) << "a ball reported on the arm";
}

TEST(TablePose, ACalibratedRigReadsAFrameWithAnArmAcrossTheTable) {
  const camera::CameraModel truth = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  const camera::CameraModel rig = RigCalibration(truth);
  cv::Mat frame = Render(truth, 2);
  DrawArm(truth, kArmFrom, kArmTo, &frame);
  DetectorOptions options;
  options.ball_radius_px = ExpectedRadiusPx(rig, Radius());
  options.calibrated = CalibratedTable{rig, Pool().table, NoseHeight(Radius())};
  BallDetector detector(options);
  std::vector<Eigen::Vector2d> found;
  for (const auto& b : detector.Detect(frame)) {
    found.push_back(rig.Unproject(b.pixel, Radius()).head<2>());
  }
  ASSERT_TRUE(detector.knows_table());
  EXPECT_EQ(detector.table()->origin, TableOrigin::kCalibrated);
  EXPECT_TRUE(detector.failure().empty()) << detector.failure();
  ExpectTheBallsBesideTheArm(found);
}

TEST(TablePose, AnEstimatorOnACalibratedRigTracksTheBallsBesideAnArm) {
  const camera::CameraModel truth = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  EstimatorOptions options;
  options.table_from_camera = true;
  BallEstimator estimator(RigCalibration(truth), Pool(), options);
  // From its first frame on, an arm lies across the table: the rig's table is not looked for.
  for (int frame = 0; frame < 3; ++frame) {
    cv::Mat image = Render(truth, 10 + frame);
    DrawArm(truth, kArmFrom, kArmTo, &image);
    ASSERT_TRUE(estimator.Process(image, frame / 30.0));
  }
  std::vector<Eigen::Vector2d> tracked;
  for (const auto& b : estimator.Balls()) tracked.push_back(b.state.head<2>());
  ExpectTheBallsBesideTheArm(tracked);
}

// A frame whose table is not found: the overhead camera moved across the table so that a long side
// is out of frame (phone photos of carom tables). (Moved along it so that a third is out, the
// table is completed from its proportions: table_partial_test.)
struct NoTable {
  const char* name;
  camera::CameraModel camera;
};

camera::CameraModel Moved(const Eigen::Vector3d& by) {
  camera::CameraModel moved = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  moved.translation = -moved.rotation * (moved.Centre() + by);
  return moved;
}

std::vector<NoTable> FramesWithoutATable() {
  // Less than half of the width seen (table_partial.h's kMinSeenShare): not completed.
  return {{"a long side and more than half the width out of frame", Moved({0, 0.8, 0})}};
}

TEST(TableFallback, WithoutATableTheBallsOnTheClothAreStillFound) {
  for (const NoTable& scene : FramesWithoutATable()) {
    const cv::Mat frame = Render(scene.camera, 3);
    const TableSearch search = FindTable(frame);
    ASSERT_FALSE(search.table) << scene.name << ": the finder found a table; the case is another";
    BallDetector detector;
    const auto found = detector.Detect(frame);
    ASSERT_TRUE(detector.table()) << scene.name;
    EXPECT_FALSE(detector.knows_table()) << scene.name;
    EXPECT_EQ(detector.failure(), search.reason) << scene.name;
    int visible = 0, matched = 0;
    for (const Eigen::Vector2d& p : Layout()) {
      const Eigen::Vector2d pixel = scene.camera.Project({p.x(), p.y(), Radius()});
      const double margin = 2 * ExpectedRadiusPx(scene.camera, Radius());
      const bool in_view = pixel.x() > margin && pixel.x() < 1280 - margin &&
                           pixel.y() > margin && pixel.y() < 720 - margin;
      if (!in_view) continue;
      ++visible;
      const bool near = std::any_of(found.begin(), found.end(), [&](const BallDetection& b) {
        return (b.pixel - pixel).norm() < 1.5;
      });
      matched += near;
      EXPECT_TRUE(near) << scene.name << ": ball at " << p.transpose() << " (pixel "
                        << pixel.transpose() << ")";
    }
    EXPECT_GE(visible, 4) << scene.name;
    EXPECT_LE(static_cast<int>(found.size()), visible + 1) << scene.name << ": false balls";
  }
}

TEST(TableFallback, ADetectorKeepsTheTableItLearntWhenALaterFrameHidesIt) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 1280, 720);
  BallDetector detector;
  ASSERT_TRUE(detector.LearnTable(Render(camera, 1)));
  const auto corners = detector.table()->corners;
  // A frame of the same camera whose table is not found: a player across most of it.
  cv::Mat hidden = Render(camera, 2);
  cv::rectangle(hidden, cv::Rect(300, 0, 700, 720), cv::Scalar(30, 30, 35), cv::FILLED);
  EXPECT_FALSE(detector.LearnTable(hidden));
  EXPECT_FALSE(detector.failure().empty());
  ASSERT_TRUE(detector.knows_table());
  for (int i = 0; i < 4; ++i) EXPECT_EQ(detector.table()->corners[i], corners[i]);
  // The balls beside the player are still found on the table learnt.
  const auto found = detector.Detect(hidden);
  const Eigen::Vector2d beside = camera.Project({Layout()[0].x(), Layout()[0].y(), Radius()});
  EXPECT_TRUE(std::any_of(found.begin(), found.end(), [&](const BallDetection& b) {
    return (b.pixel - beside).norm() < 1.5;
  })) << "the ball at " << Layout()[0].transpose();
}

}  // namespace
}  // namespace billiard::estimator
