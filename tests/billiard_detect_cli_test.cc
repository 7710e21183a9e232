// `billiard detect` and `billiard calibrate` as a user runs them on the real photograph: one JSON
// object on stdout, every ball once; a missing or unreadable image is a usage error (exit 2,
// one line).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "estimator/testing/real_table_photo.h"
#include "tests/support/billiard_command.h"
#include "tests/support/test_data.h"

namespace {

using billiard::estimator::testing::HandBall;
using billiard::estimator::testing::kRealTablePhoto;
using billiard::testing::Billiard;
using billiard::testing::CommandResult;
using billiard::testing::OneObject;

// Each hand-listed ball exactly once within 4 px, and nothing else.
void ExpectEveryBallOnce(const nlohmann::json& balls) {
  ASSERT_EQ(balls.size(), 21u) << balls;
  std::vector<int> used(balls.size(), 0);
  for (const HandBall& hand : billiard::estimator::testing::RealTablePhotoBalls()) {
    int times = 0;
    for (std::size_t i = 0; i < balls.size(); ++i) {
      const double du = balls[i]["u"].get<double>() - hand.pixel.x();
      const double dv = balls[i]["v"].get<double>() - hand.pixel.y();
      if (std::hypot(du, dv) < 4.0) {
        ++times;
        ++used[i];
      }
    }
    EXPECT_EQ(times, 1) << hand.name << " at " << hand.pixel.transpose();
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 1), 21);
}

// The commands on the real photograph, skipped with the reason where the test data is absent.
class BilliardDetect : public ::testing::Test {
 protected:
  void SetUp() override {
    photo_ = billiard::testing::TestDataPath(kRealTablePhoto);
    if (photo_.empty()) GTEST_SKIP() << billiard::testing::MissingTestData(kRealTablePhoto);
  }
  const std::string& photo() const { return photo_; }

 private:
  std::string photo_;
};

TEST_F(BilliardDetect, FindsTheTwentyOneBallsOfTheRealPhotograph) {
  for (const std::string options : {"", " --ball-radius-px 15"}) {
    const std::string args = "detect " + photo() + options + " --json";
    const CommandResult r = Billiard(args);
    ASSERT_EQ(r.status, 0) << args;
    const auto j = OneObject(r, args);
    ExpectEveryBallOnce(j["balls"]);
    for (const auto& ball : j["balls"]) {
      for (const char* key : {"u", "v", "radius_px", "score"}) EXPECT_TRUE(ball.contains(key)) << ball;
      EXPECT_FALSE(ball.contains("x")) << "table coordinates need --calib";
      EXPECT_GE(ball["score"].get<double>(), 0.5);
      EXPECT_LE(ball["score"].get<double>(), 1.0);
      EXPECT_NEAR(ball["radius_px"].get<double>(), 15.0, 2.5);
    }
  }
}

TEST_F(BilliardDetect, TableCoordinatesFromACalibration) {
  // The photo's geometry read off by hand: a pool ball (radius 28.575 mm) is 15 px in radius, so
  // 1.905 mm per pixel; the cloth's bottom-left corner is at pixel (80, 665). The markers' table
  // coordinates follow from their pixels.
  constexpr double kMetresPerPixel = 0.028575 / 15.0;
  const auto table = [&](double u, double v) {
    return std::to_string((u - 80) * kMetresPerPixel) + "," + std::to_string((665 - v) * kMetresPerPixel);
  };
  const std::string markers = table(144, 37) + "," + table(1177, 34) + "," + table(1172, 683) +
                              "," + table(149, 681);
  char dir[] = "/tmp/billiard_detect_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string camera = std::string(dir) + "/camera.json";
  const std::string& photo = this->photo();
  const std::string calibrate =
      "calibrate " + photo + " --params pool --markers=" + markers + " --out " + camera + " --json";
  const CommandResult c = Billiard(calibrate);
  ASSERT_EQ(c.status, 0) << calibrate;
  EXPECT_LT(OneObject(c, calibrate)["rms_reprojection_px"].get<double>(), 3.0);

  const std::string detect = "detect " + photo + " --calib " + camera + " --params pool --json";
  const CommandResult r = Billiard(detect);
  ASSERT_EQ(r.status, 0) << detect;
  const auto j = OneObject(r, detect);
  ExpectEveryBallOnce(j["balls"]);
  for (const auto& ball : j["balls"]) {
    ASSERT_TRUE(ball.contains("x") && ball.contains("y")) << ball;
    // Where the hand-read scale puts it, within a centimetre (the markers' pose is only as good
    // as that scale and the guessed focal length).
    const double x = (ball["u"].get<double>() - 80) * kMetresPerPixel;
    const double y = (665 - ball["v"].get<double>()) * kMetresPerPixel;
    EXPECT_NEAR(ball["x"].get<double>(), x, 0.01) << ball;
    EXPECT_NEAR(ball["y"].get<double>(), y, 0.01) << ball;
  }
  std::filesystem::remove_all(dir);
}

TEST_F(BilliardDetect, BadInputExitsTwoWithAOneLineReason) {
  char dir[] = "/tmp/billiard_detect_XXXXXX";
  ASSERT_NE(mkdtemp(dir), nullptr);
  const std::string empty = std::string(dir) + "/empty.png", text = std::string(dir) + "/text.png";
  std::ofstream(empty).close();
  std::ofstream(text) << "not an image\n";
  const std::string& photo = this->photo();
  const std::string bad[] = {
      "detect /no/such/image.png --json",
      "detect " + empty + " --json",
      "detect " + text + " --json",
      "detect --json",
      "detect " + photo + " --ball-radius-px nan --json",
      "detect " + photo + " --ball-radius-px=-3 --json",
      "detect " + photo + " --calib /no/such/camera.json --json",
      "detect " + photo + " --calib " + text + " --json",
      "calibrate " + empty + " --out " + std::string(dir) + "/camera.json --json",
  };
  for (const std::string& args : bad) {
    const CommandResult r = Billiard(args, true);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(r.out.find('{'), std::string::npos) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
  }
  std::filesystem::remove_all(dir);
}

TEST_F(BilliardDetect, HumanSummaryGoesToStderr) {
  const CommandResult r = Billiard("detect " + photo());
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace
