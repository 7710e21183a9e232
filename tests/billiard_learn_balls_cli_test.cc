// `billiard learn-balls` and `detect --ball-model` as a user runs them on a rendered rig: the
// sixteen pool balls set out in a row, placed in pixels or on the table through the camera's
// calibration, learnt into a model that names every ball of another layout under a warmer light;
// a placing file that is not one is a usage error (2), a frame none of whose placed balls is
// found is refused (3, no model written), a placed ball not found is said and left out.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "sim/camera/camera_model.h"
#include "sim/params/parameter_sets.h"
#include "sim/render/table_renderer.h"
#include "tests/support/billiard_command.h"

namespace {

using billiard::testing::Billiard;
using billiard::testing::OneObject;
namespace camera = billiard::camera;
namespace render = billiard::render;

const billiard::physics::ModelParameters& Pool() {
  static const auto params = billiard::params::LoadParameters("pool");
  return params;
}

camera::CameraModel Rig() { return camera::CameraModel::Overhead(Pool().table, 1280, 720); }

// A ball of the frame: its id (0 the cue ball) and where it lies on the table.
struct Ball {
  int id;
  Eigen::Vector2d xy;
};

// The sixteen in a row along the table; the same shuffled over the cloth.
std::vector<Ball> InARow() {
  std::vector<Ball> balls;
  for (int id = 0; id <= 15; ++id) balls.push_back({id, {0.3 + 0.13 * id, 0.45}});
  return balls;
}

std::vector<Ball> Elsewhere() {
  std::vector<Ball> balls;
  for (int id = 0; id <= 15; ++id) {
    balls.push_back({id, {0.25 + 0.28 * (id % 8), 0.3 + 0.5 * (id / 8) + 0.04 * (id % 3)}});
  }
  return balls;
}

Eigen::Vector2d Pixel(const Ball& b) {
  return Rig().Project({b.xy.x(), b.xy.y(), Pool().ball.radius});
}

std::string Name(int id) { return id == 0 ? "cue" : std::to_string(id); }

class LearnBallsCli : public ::testing::Test {
 protected:
  void SetUp() override {
    char name[] = "/tmp/billiard_learn_balls_XXXXXX";
    ASSERT_NE(mkdtemp(name), nullptr);
    dir_ = name;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }

  // The frame of `balls` under a light of `light` (B, G, R gains), written as `name`.
  std::string Frame(const std::string& name, const std::vector<Ball>& balls,
                    const cv::Vec3f& light) const {
    render::RenderOptions options;
    options.light_colour = light;
    std::vector<render::RenderBall> shown;
    for (const Ball& b : balls) {
      shown.push_back(render::RenderBall::AtRest(b.id, render::PoolBallColour(b.id), b.xy));
      shown.back().striped = render::PoolBallStriped(b.id);
    }
    cv::imwrite(Path(name), render::TableRenderer(Rig(), Pool(), options).Render(shown, 0.0));
    return Path(name);
  }

  std::string Write(const std::string& name, const std::string& text) const {
    std::ofstream(Path(name)) << text;
    return Path(name);
  }

  // The placing file of `balls`: in pixels, or on the table.
  std::string Placing(const std::string& name, const std::vector<Ball>& balls,
                      bool on_table) const {
    nlohmann::json list = nlohmann::json::array();
    for (const Ball& b : balls) {
      const Eigen::Vector2d p = on_table ? b.xy : Pixel(b);
      list.push_back(on_table ? nlohmann::json{{"id", Name(b.id)}, {"x", p.x()}, {"y", p.y()}}
                              : nlohmann::json{{"id", b.id}, {"u", p.x()}, {"v", p.y()}});
    }
    return Write(name, list.dump());
  }

  std::string dir_;
};

// Learnt from the row in pixels, and again on the table through the calibration: the same model
// names every ball of another layout under a tungsten light.
TEST_F(LearnBallsCli, ARowLearntNamesEveryBallOfAnotherLayoutUnderAnotherLight) {
  const std::string row = Frame("row.png", InARow(), {1, 1, 1});
  const std::string calib = Write("camera.json", camera::CameraModelJson(Rig()));
  for (const bool on_table : {false, true}) {
    const std::string args = row + " --balls " + Placing("balls.json", InARow(), on_table) +
                             (on_table ? " --calib " + calib : "") + " --out " +
                             Path("model.json") + " --json";
    const auto r = Billiard("learn-balls " + args);
    ASSERT_EQ(r.status, 0) << args << ": " << r.out;
    const auto j = OneObject(r, args);
    EXPECT_EQ(j["learnt"], 16) << args;
    EXPECT_EQ(j["named_right_model"], 16) << args;
    EXPECT_TRUE(j["missing"].empty()) << args;
  }
  const std::string other = Frame("other.png", Elsewhere(), {0.55f, 0.8f, 1.0f});
  const std::string args = other + " --ball-model " + Path("model.json") + " --json";
  const auto r = Billiard("detect " + args);
  ASSERT_EQ(r.status, 0) << args << ": " << r.out;
  const auto found = OneObject(r, args)["balls"];
  for (const Ball& b : Elsewhere()) {
    int named_right = 0;
    for (const auto& f : found) {
      const bool here = (Eigen::Vector2d(f["u"], f["v"]) - Pixel(b)).norm() < 3.0;
      named_right += here && f["class"] == Name(b.id);
    }
    EXPECT_EQ(named_right, 1) << "ball " << Name(b.id);
  }
  // A model of pool balls names no snooker set.
  const auto snooker = Billiard("detect " + args + " --ball-set snooker", true);
  EXPECT_EQ(snooker.status, 2) << snooker.out;
  EXPECT_NE(snooker.out.find("is a model of pool balls"), std::string::npos) << snooker.out;
}

TEST_F(LearnBallsCli, APlacingThatIsNotOneIsAUsageErrorAndNothingFoundIsRefused) {
  const std::string row = Frame("row.png", InARow(), {1, 1, 1});
  const std::string out = " --out " + Path("model.json");
  for (const std::string& text :
       {std::string("{}"), std::string("[{\"id\": \"3\", \"x\": 1, \"y\": 0.5}]"),
        std::string("[{\"id\": \"pink\", \"u\": 1, \"v\": 2}]"),
        std::string("[{\"id\": 3, \"u\": 1, \"v\": 2}, {\"id\": \"3\", \"u\": 9, \"v\": 2}]")}) {
    const auto r = Billiard("learn-balls " + row + " --balls " + Write("b.json", text) + out, true);
    EXPECT_EQ(r.status, 2) << text << ": " << r.out;
    EXPECT_NE(r.out.find("--balls"), std::string::npos) << r.out;
  }
  // Placed where no ball lies: one is said and left out; all, and the frame is refused.
  std::vector<Ball> off = InARow();
  off[5].xy.y() += 0.3;
  auto r = Billiard("learn-balls " + row + " --balls " + Placing("b.json", off, false) + out +
                        " --json",
                    true);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("no ball found where ball 5 is placed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"missing\":[\"5\"]"), std::string::npos) << r.out;
  for (Ball& b : off) b.xy.y() += 0.3;
  std::filesystem::remove(Path("model.json"));
  r = Billiard("learn-balls " + row + " --balls " + Placing("b.json", off, false) + out, true);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_FALSE(std::filesystem::exists(Path("model.json")));
  // A model that is not one, or of another set than --ball-set's, is a usage error of detect.
  for (const std::string& option : {" --ball-model " + Write("m.json", "{}"),
                                    " --ball-model " + Path("none.json")}) {
    r = Billiard("detect " + row + option, true);
    EXPECT_EQ(r.status, 2) << option << ": " << r.out;
    EXPECT_NE(r.out.find("--ball-model: "), std::string::npos) << r.out;
  }
}

}  // namespace
