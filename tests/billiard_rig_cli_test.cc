// A rig learned once, without markers, as a user runs it on rendered frames with known truth:
// `billiard calibrate` from the table found (or its corners given), `billiard detect --calib` on a
// later frame with an arm across the table, its balls written with --scene-out and read by
// `choose-shot --scene`; and `detect` on a frame whose table is not found: the balls on the cloth
// in image coordinates, "table": null and the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "sim/params/parameter_sets.h"
#include "sim/params/scene_file.h"
#include "sim/render/table_renderer.h"
#include "tests/support/billiard_command.h"

namespace billiard::testing {
namespace {

namespace fs = std::filesystem;

const std::string kLayout = std::string(PROJECT_SOURCE_DIR) + "/tests/data/nine_ball_layout.json";
// How close [m] a ball's position read through a calibration without markers is to the truth.
constexpr double kPositionBound = 0.003;

const physics::ModelParameters& Pool() {
  static const physics::ModelParameters params = params::LoadParameters("pool");
  return params;
}

std::string Scratch(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "billiard_rig_cli_test";
  fs::create_directories(dir);
  return (dir / name).string();
}

// The nine-ball layout of tests/data (the truth), rendered by `camera` (the cushions at the
// noses' height of the calibration, 63.5 % of a ball), written as a PNG.
std::string RenderLayout(const camera::CameraModel& camera, std::uint64_t seed,
                         const std::string& name, bool arm) {
  render::RenderOptions options;
  options.exposure_s = 0;
  options.seed = seed;
  options.cushion_height = 0.635 * 2 * Pool().ball.radius;
  std::vector<render::RenderBall> balls;
  for (const auto& b : params::LoadScene(kLayout).balls) {
    balls.push_back(render::RenderBall::AtRest(b.id, render::PoolBallColour(b.id),
                                               b.state.head<2>()));
  }
  cv::Mat frame = render::TableRenderer(camera, Pool(), options).Render(balls, 0.0);
  if (arm) {
    // A dark sleeve across the whole table, rail to rail, 12 cm wide, between the balls.
    std::vector<cv::Point> sleeve;
    for (const Eigen::Vector3d& p :
         {Eigen::Vector3d(1.80, -0.3, 0.1), Eigen::Vector3d(1.92, -0.3, 0.1),
          Eigen::Vector3d(2.02, 1.6, 0.1), Eigen::Vector3d(1.90, 1.6, 0.1)}) {
      const Eigen::Vector2d q = camera.Project(p);
      sleeve.emplace_back(static_cast<int>(std::lround(q.x())),
                          static_cast<int>(std::lround(q.y())));
    }
    cv::fillConvexPoly(frame, sleeve, cv::Scalar(45, 50, 60), cv::LINE_AA);
  }
  const std::string path = Scratch(name);
  EXPECT_TRUE(cv::imwrite(path, frame));
  return path;
}

camera::CameraModel Overhead() { return camera::CameraModel::Overhead(Pool().table, 1280, 720); }

// The truth ball nearest (x, y) and its distance [m].
std::pair<int, double> NearestTruth(double x, double y) {
  std::pair<int, double> best{-1, HUGE_VAL};
  for (const auto& b : params::LoadScene(kLayout).balls) {
    const double d = (b.state.head<2>() - Eigen::Vector2d(x, y)).norm();
    if (d < best.second) best = {b.id, d};
  }
  return best;
}

TEST(BilliardRig, CalibratedFromTheTableThenReadThroughAnArmToAChosenShot) {
  const std::string camera = Scratch("camera.json"), scene = Scratch("scene.json");
  const std::string calibrate =
      "calibrate " + RenderLayout(Overhead(), 1, "rig.png", false) + " --out " + camera + " --json";
  const CommandResult c = Billiard(calibrate);
  ASSERT_EQ(c.status, 0) << calibrate << ": " << c.out;
  const nlohmann::json fit = OneObject(c, calibrate);
  EXPECT_EQ(fit["from"], "table");
  EXPECT_LT(fit["rms_reprojection_px"].get<double>(), 1.0);

  const std::string detect = "detect " + RenderLayout(Overhead(), 2, "arm.png", true) +
                             " --calib " + camera + " --scene-out " + scene + " --json";
  const CommandResult d = Billiard(detect);
  ASSERT_EQ(d.status, 0) << detect << ": " << d.out;
  const nlohmann::json found = OneObject(d, detect);
  EXPECT_EQ(found["table"]["from"], "calibration");
  EXPECT_EQ(found["balls"].size(), 10u) << "every ball of the layout, none on the arm";
  for (const auto& b : found["balls"]) {
    EXPECT_LT(NearestTruth(b["x"], b["y"]).second, kPositionBound) << b.dump();
  }

  // The scene: every ball where the truth has it, the cue ball named, and choose-shot reads it.
  const params::SceneFile written = params::LoadScene(scene);
  EXPECT_EQ(written.balls.size(), 10u);
  int named_right = 0;
  for (const auto& b : written.balls) {
    const auto [id, distance] = NearestTruth(b.state[0], b.state[1]);
    EXPECT_LT(distance, kPositionBound) << "ball " << b.id;
    named_right += id == b.id;
    if (b.id == 0) EXPECT_EQ(id, 0) << "the cue ball";
  }
  EXPECT_GE(named_right, 8) << "the balls' ids are their classes";
  const std::string choose = "choose-shot --scene " + scene + " --samples 16 --json";
  const CommandResult s = Billiard(choose);
  EXPECT_EQ(s.status, 0) << choose << ": " << s.out;
  EXPECT_TRUE(OneObject(s, choose).contains("choice"));
}

TEST(BilliardRig, CornersGivenCalibrateAsTheTableFound) {
  // The overhead camera sees every cushion's face: the corners are where the faces meet the cloth.
  std::string corners;
  const double l = Pool().table.length, w = Pool().table.width;
  for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, w, 0), Eigen::Vector3d(l, w, 0),
                                   Eigen::Vector3d(l, 0, 0), Eigen::Vector3d(0, 0, 0)}) {
    const Eigen::Vector2d q = Overhead().Project(p);
    corners += (corners.empty() ? "" : ";") + std::to_string(q.x()) + "," + std::to_string(q.y());
  }
  const std::string camera = Scratch("given.json");
  const std::string calibrate = "calibrate " + RenderLayout(Overhead(), 1, "given.png", false) +
                                " --corners '" + corners + "' --out " + camera + " --json";
  const CommandResult c = Billiard(calibrate);
  ASSERT_EQ(c.status, 0) << calibrate << ": " << c.out;
  EXPECT_EQ(OneObject(c, calibrate)["from"], "corners");
  const camera::CameraModel fitted = camera::LoadCameraModel(camera);
  for (const auto& b : params::LoadScene(kLayout).balls) {
    const Eigen::Vector3d p(b.state[0], b.state[1], Pool().ball.radius);
    EXPECT_LT((fitted.Unproject(Overhead().Project(p), p.z()) - p).norm(), kPositionBound);
  }
  EXPECT_EQ(Billiard("calibrate x.png --corners '1,2;3,4' --out " + camera).status, 2);
  EXPECT_EQ(Billiard("detect x.png --scene-out " + Scratch("s.json")).status, 2);
}

TEST(BilliardRig, WithoutATableTheBallsOnTheClothInImageCoordinates) {
  // The camera moved across the table: a long side and more than half of the width out of frame,
  // less than the finder completes (table_partial.h's kMinSeenShare).
  camera::CameraModel moved = Overhead();
  moved.translation = -moved.rotation * (moved.Centre() + Eigen::Vector3d(0, -0.8, 0));
  const std::string args = "detect " + RenderLayout(moved, 3, "part.png", false) + " --json";
  const CommandResult r = Billiard(args);
  ASSERT_EQ(r.status, 0) << args << ": " << r.out;
  const nlohmann::json j = OneObject(r, args);
  EXPECT_TRUE(j["table"].is_null());
  EXPECT_NE(j.value("no_table", ""), "");
  // The part seen: the table runs out of the frame through the frame's top edge alone.
  const nlohmann::json& edges = j["cloth_at_frame_edges"];
  EXPECT_GT(edges["top"].get<double>(), 0.5) << edges;
  for (const char* edge : {"left", "bottom", "right"}) EXPECT_EQ(edges[edge], 0.0) << edge;
  int in_view = 0, in_frame = 0;
  for (const auto& b : params::LoadScene(kLayout).balls) {
    const Eigen::Vector2d p = moved.Project({b.state[0], b.state[1], Pool().ball.radius});
    in_frame += p.x() >= 0 && p.x() < 1280 && p.y() >= 0 && p.y() < 720;
    if (p.x() < 40 || p.x() > 1240 || p.y() < 40 || p.y() > 680) continue;
    ++in_view;
    bool seen = false;
    for (const auto& f : j["balls"]) {
      seen = seen || (Eigen::Vector2d(f["u"], f["v"]) - p).norm() < 1.5;
      EXPECT_FALSE(f.contains("x")) << "no table coordinates without a table";
    }
    EXPECT_TRUE(seen) << "ball " << b.id << " at " << p.transpose();
  }
  EXPECT_GE(in_view, 5);
  EXPECT_LE(j["balls"].size(), static_cast<std::size_t>(in_frame));
}

}  // namespace
}  // namespace billiard::testing
