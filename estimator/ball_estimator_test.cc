// The estimator's refusals (frames it cannot take), a break tracked at the loop's camera rate
// against the whole-table simulation's truth, and the positions of a ball at rest through the
// loop's JPEG without a scale about the camera's axis. Its accuracy on rendered shots is measured
// in bench/estimator_benchmark_test.cc.
#include "estimator/ball_estimator.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/render/table_renderer.h"
#include "sim/table/rack.h"
#include "sim/table/table_simulation.h"

namespace billiard::estimator {
namespace {

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters p = params::LoadParameters("pool");
  return p;
}

TEST(BallEstimator, RefusesEmptyMisSizedAndBackwardFrames) {
  const camera::CameraModel camera = camera::CameraModel::Overhead(Pool().table, 640, 360);
  BallEstimator estimator(camera, Pool());
  const cv::Mat frame = render::TableRenderer(camera, Pool()).Render({}, 0.0);
  EXPECT_FALSE(estimator.Process(cv::Mat(), 0.0));
  EXPECT_FALSE(estimator.Process(cv::Mat(100, 100, CV_8UC3, cv::Scalar(0, 0, 0)), 0.0));
  EXPECT_TRUE(estimator.Process(frame, 1.0));
  EXPECT_FALSE(estimator.Process(frame, 0.5));
  EXPECT_TRUE(estimator.Balls().empty());
}

// The loop's break (run_loop.sh --scene break): the eight-ball rack, the cue ball rolling into
// its head ball at `break_speed` (below, 7 m/s: issue 27's fast cue ball, 28 mm of motion blur in
// the 4 ms exposure; at 9 m/s, beyond TrackerOptions::max_speed, its first frame after the strike
// falls outside the association's gate and starts a track of its own), seen from overhead at
// 1280x720 and 30 frames a second, the stripes striped as table_sim_node renders them (or not),
// the truth from the whole-table simulation. Every ball on the table is tracked in every frame from the first
// (a sure detection is published at once), within 5 mm (a racked ball sent off at 2 m/s, or the
// cue ball struck from rest, moves 50-230 mm between frames: the track must follow the jump,
// not a fraction of it), its track never another ball's.
void ExpectABreakTrackedAtThirtyFramesASecond(double break_speed, bool stripes_striped) {
  constexpr double kRate = 30.0, kStrike = 0.1, kAfter = 3.0;  // [Hz], [s], [s]
  constexpr double kMaxErrorMm = 5.0;
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius;
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  std::vector<table::SceneBall> balls =
      table::Rack(table::RackKind::kEightBall, geometry, r, /*seed=*/1);
  // The cue ball rolls straight at the ball nearest it.
  const Eigen::Vector2d cue = balls[0].state.head<2>();
  Eigen::Vector2d head(1e9, 1e9);
  for (std::size_t i = 1; i < balls.size(); ++i) {
    const Eigen::Vector2d x = balls[i].state.head<2>();
    if ((x - cue).norm() < (head - cue).norm()) head = x;
  }
  const Eigen::Vector2d v = break_speed * (head - cue).normalized();
  balls[0].state = physics::MakeBallState(cue.x(), cue.y(), v.x(), v.y(), -v.y() / r, v.x() / r, 0);
  table::TableSimulation sim(geometry, p, balls);
  sim.Run(kAfter);

  const camera::CameraModel camera = camera::CameraModel::Overhead(p.table, 1280, 720);
  const render::TableRenderer renderer(camera, p);
  std::vector<render::RenderBall> shown;
  for (std::size_t i = 0; i < sim.ball_count(); ++i) {
    const table::SceneBall rest = balls[i];
    shown.push_back({sim.id(i), render::PoolBallColour(sim.id(i)),
                     [&sim, i, rest](double t) {
                       return t < kStrike ? Eigen::Vector2d(rest.state.head<2>())
                                          : Eigen::Vector2d(sim.StateAt(i, t - kStrike).head<2>());
                     },
                     stripes_striped && render::PoolBallStriped(sim.id(i))});
  }
  BallEstimator estimator(camera, p);
  std::map<int, int> track_of;  // ball id -> its track
  int lost = 0, swaps = 0;
  double worst = 0.0;
  for (int f = 0; f / kRate <= kStrike + kAfter; ++f) {
    const double t = f / kRate;
    std::vector<render::RenderBall> on_table;
    for (std::size_t i = 0; i < shown.size(); ++i) {
      const bool dropped = sim.pocket(i) && t - kStrike >= sim.segments(i).back().start_time();
      if (!dropped) on_table.push_back(shown[i]);
    }
    ASSERT_TRUE(estimator.Process(renderer.Render(on_table, t), t));
    const std::vector<TrackedBall> tracks = estimator.Balls();
    for (const render::RenderBall& ball : on_table) {
      const Eigen::Vector2d truth = ball.position(t);
      const TrackedBall* nearest = nullptr;
      for (const TrackedBall& track : tracks) {
        if (!nearest || (track.position() - truth).norm() < (nearest->position() - truth).norm())
          nearest = &track;
      }
      if (!nearest || (nearest->position() - truth).norm() > r) {
        ++lost;
        ADD_FAILURE() << "ball " << ball.id << " has no track at t = " << t << " s";
        continue;
      }
      const double error = (nearest->position() - truth).norm();
      worst = std::max(worst, error);
      EXPECT_LE(1e3 * error, kMaxErrorMm) << "ball " << ball.id << " at t = " << t << " s";
      const auto mapped = track_of.find(ball.id);
      if (mapped != track_of.end() && mapped->second != nearest->id) {
        ++swaps;
        ADD_FAILURE() << "ball " << ball.id << " changed tracks at t = " << t << " s";
      }
      track_of[ball.id] = nearest->id;
    }
  }
  EXPECT_EQ(lost, 0);
  EXPECT_EQ(swaps, 0);
  ::testing::Test::RecordProperty("worst_error_mm", std::to_string(1e3 * worst));
}

TEST(BallEstimator, TracksEveryBallThroughABreakAtThirtyFramesASecond) {
  ExpectABreakTrackedAtThirtyFramesASecond(7.0, true);
}

// The same break at 5 m/s with the stripes drawn as solids: every object ball has a twin (the 1
// and the 9, ...), so no detection tells the racked balls apart (the rack's margin, the class's
// confidence, is 0), as snooker's reds cannot be. The cue ball, stopped dead by the head ball and
// detected beside the balls it pushed on, keeps its track by its class alone: the cue ball's
// track holds it surely (without it, the cue ball took the track of the ball beside it).
TEST(BallEstimator, TheCueBallKeepsItsTrackAmongBallsItCannotBeToldFrom) {
  ExpectABreakTrackedAtThirtyFramesASecond(5.0, false);
}

// The loop's camera (table_sim_node's: overhead, 1280x720) and its frames as the estimator gets
// them: rendered, then the loop's JPEG (quality 90, table_sim_node.h), decoded.
constexpr int kLoopWidth = 1280, kLoopHeight = 720, kLoopJpegQuality = 90;

cv::Mat ThroughTheLoopsJpeg(const cv::Mat& frame) {
  std::vector<unsigned char> jpeg;
  cv::imencode(".jpg", frame, jpeg, {cv::IMWRITE_JPEG_QUALITY, kLoopJpegQuality});
  return cv::imdecode(jpeg, cv::IMREAD_COLOR);
}

// The least-squares fit of errors e_i = s (x_i - c) + t: the radial scale s about c and a shift t.
struct ScaleAndShift {
  double scale = 0;
  Eigen::Vector2d shift;
};

ScaleAndShift RadialScale(const std::vector<Eigen::Vector2d>& truth,
                          const std::vector<Eigen::Vector2d>& seen, const Eigen::Vector2d& c) {
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Vector2d d = truth[i] - c, e = seen[i] - truth[i];
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Vector3d j(d[axis], axis == 0, axis == 1);
      normal += j * j.transpose();
      right += j * e[axis];
    }
  }
  const Eigen::Vector3d fit = normal.ldlt().solve(right);
  return {fit[0], fit.tail<2>()};
}

// Where an exact outline puts a sphere of radius r at rest at `xy`: a sphere off the camera's
// axis projects to an ellipse symmetric about the line from the principal point through it, whose
// vertices on that line are the images of the two points where the rays in the plane of the axis
// and the centre graze the sphere; the ellipse's centre, their midpoint, back on the table at the
// height of the ball's centre (as the estimator reads a pixel).
Eigen::Vector2d SilhouetteCentre(const camera::CameraModel& camera, const Eigen::Vector2d& xy,
                                 double r) {
  const Eigen::Vector3d eye = camera.Centre(), centre(xy.x(), xy.y(), r);
  const double d = (centre - eye).norm();
  const Eigen::Vector3d w = (centre - eye) / d;
  const Eigen::Vector3d axis = camera.rotation.row(2).transpose();
  const Eigen::Vector3d across = (axis - axis.dot(w) * w).normalized();
  const Eigen::Vector3d rim = centre - (r * r / d) * w;  // the centre of the grazing circle
  const double rim_radius = r * std::sqrt(1.0 - r * r / (d * d));
  const Eigen::Vector2d middle =
      0.5 * (camera.Project(rim + rim_radius * across) + camera.Project(rim - rim_radius * across));
  return camera.Unproject(middle, r).head<2>();
}

// The cue ball (the loop's shots strike it alone) at rest at 12 places over the table, each
// seen for kFrames frames (their sensor noise independent) by an estimator of its own, through
// the loop's JPEG: the estimated positions against the truth have a radial scale about the
// camera's axis (the table's centre) of less than 0.02 % (0.2 mm a metre from the centre), and
// what is left after the scale and a shift is within 0.4 mm at each place. A scale e of the
// positions is read by the adaptive loop's identification as mu_r (1 + e), and its plans then
// miss by about e |T + c - 2 p| (docs/benchmarks/adaptive_loop_report.md). The outline's edges
// at their fastest change of colour alone gave +0.087 %; placed on the chroma
// (CentreOnChroma), +0.009 %. The truth sanity: the exact silhouettes' centres are outward of
// the balls' by the sphere's perspective, which the renderer's header gives as
// f (r / D)^2 tan(theta) / cos^2(theta) pixels (D the distance, theta the angle off the axis), a
// scale of about +0.013 % here, within the bound: a perfect outline would meet it.
TEST(BallEstimator, PositionsAtRestThroughTheLoopsJpegKeepTheirScale) {
  constexpr int kFrames = 4;
  constexpr double kRate = 30.0;                  // [Hz]
  constexpr double kMaxScale = 2e-4;              // 0.02 %
  constexpr double kMaxResidualMm = 0.4;          // each place, after the scale and shift
  constexpr double kPerspectiveAgreement = 0.05;  // of the header's approximation
  const physics::ModelParameters& p = Pool();
  const double r = p.ball.radius;
  const camera::CameraModel camera =
      camera::CameraModel::Overhead(p.table, kLoopWidth, kLoopHeight);
  const render::TableRenderer renderer(camera, p);
  const Eigen::Vector2d axis = camera.Unproject({camera.cx, camera.cy}, r).head<2>();
  std::vector<Eigen::Vector2d> truth, seen, silhouette;
  for (const double x : {0.3, 0.9, 1.65, 2.25}) {
    for (const double y : {0.25, 0.7, 1.05}) {
      const Eigen::Vector2d place(x, y);
      BallEstimator estimator(camera, p);
      const std::vector<render::RenderBall> balls = {
          render::RenderBall::AtRest(0, render::PoolBallColour(0), place)};
      for (int f = 0; f < kFrames; ++f) {
        ASSERT_TRUE(
            estimator.Process(ThroughTheLoopsJpeg(renderer.Render(balls, f / kRate)), f / kRate));
      }
      const std::vector<TrackedBall> tracks = estimator.Balls();
      ASSERT_EQ(tracks.size(), 1u) << "at " << place.transpose();
      truth.push_back(place);
      seen.push_back(tracks[0].position());
      silhouette.push_back(SilhouetteCentre(camera, place, r));
      // The sanity: the silhouette's shift against the header's approximation.
      const Eigen::Vector3d centre(x, y, r);
      const Eigen::Vector3d in_camera = camera.rotation * centre + camera.translation;
      const double theta = std::atan2(in_camera.head<2>().norm(), in_camera.z());
      const double predicted_px = camera.fx * std::pow(r / in_camera.norm(), 2) * std::tan(theta) /
                                  std::pow(std::cos(theta), 2);
      const double shift_px = (camera.Project({silhouette.back().x(), silhouette.back().y(), r}) -
                               camera.Project(centre))
                                  .norm();
      EXPECT_NEAR(shift_px, predicted_px, kPerspectiveAgreement * predicted_px)
          << "at " << place.transpose();
    }
  }
  const ScaleAndShift fit = RadialScale(truth, seen, axis);
  const double scale = fit.scale, perspective = RadialScale(truth, silhouette, axis).scale;
  RecordProperty("radial_scale_percent", std::to_string(100 * scale));
  RecordProperty("silhouette_scale_percent", std::to_string(100 * perspective));
  EXPECT_GT(perspective, 0.0);
  EXPECT_LT(perspective, kMaxScale);
  EXPECT_LT(std::abs(scale), kMaxScale);
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const Eigen::Vector2d expected = truth[i] + scale * (truth[i] - axis) + fit.shift;
    EXPECT_LT(1e3 * (seen[i] - expected).norm(), kMaxResidualMm) << "at " << truth[i].transpose();
  }
}

}  // namespace
}  // namespace billiard::estimator
