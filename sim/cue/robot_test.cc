#include "sim/cue/robot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace billiard::cue {
namespace {

constexpr double kDegree = M_PI / 180.0;

Robot Valid() {
  Robot robot;
  robot.name = "test";
  robot.cue = {1.47, 0.0065, 0.0155};
  robot.bridge = 0.2;
  robot.elevation = {0.0, 60 * kDegree};
  robot.max_tip_offset = 0.5;
  robot.speed = {0.0, 8.0};
  robot.gantry = Gantry{0.5, 0.01};
  robot.noise = "robot";
  return robot;
}

TEST(RobotTest, TheCueTapersLinearlyFromTipToButt) {
  const CueShape cue{1.47, 0.0065, 0.0155};
  EXPECT_DOUBLE_EQ(cue.RadiusAt(0.0), 0.0065);
  EXPECT_DOUBLE_EQ(cue.RadiusAt(1.47), 0.0155);
  EXPECT_DOUBLE_EQ(cue.RadiusAt(0.735), 0.011);  // the middle's radius: the mean of the ends
  EXPECT_DOUBLE_EQ(cue.Taper(), 0.009 / 1.47);
}

void ExpectRefused(const std::function<void(Robot*)>& spoil, const std::string& reason) {
  Robot robot = Valid();
  spoil(&robot);
  try {
    ValidateRobot(robot);
    ADD_FAILURE() << "accepted; expected: " << reason;
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), reason);
  }
}

TEST(RobotTest, ValidatesEveryNumber) {
  EXPECT_NO_THROW(ValidateRobot(Valid()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ExpectRefused([&](Robot* r) { r->cue.length = nan; }, "a number is not finite");
  ExpectRefused([](Robot* r) { r->cue.length = 0; }, "cue.length must be positive");
  ExpectRefused([](Robot* r) { r->cue.tip_radius = 0; }, "cue.tip_radius must be positive");
  ExpectRefused([](Robot* r) { r->cue.butt_radius = 0.006; },
                "cue.butt_radius must be at least cue.tip_radius");
  ExpectRefused([](Robot* r) { r->cue.butt_radius = 2.0; },
                "cue.butt_radius must be below cue.length");
  ExpectRefused([](Robot* r) { r->bridge = 1.5; }, "bridge must be in [0, cue.length]");
  ExpectRefused([](Robot* r) { r->elevation.min = -0.1; },
                "elevation_deg.min must be in [0, elevation_deg.max]");
  ExpectRefused(
      [](Robot* r) {
        r->elevation = {0.5, 0.4};
      },
      "elevation_deg.min must be in [0, elevation_deg.max]");
  ExpectRefused([](Robot* r) { r->elevation.max = M_PI / 2; },
                "elevation_deg.max must be below 90");
  ExpectRefused([](Robot* r) { r->max_tip_offset = 1.0; }, "max_tip_offset must be in (0, 1)");
  ExpectRefused(
      [](Robot* r) {
        r->speed = {2.0, 1.0};
      },
      "speed_mps.min must be in [0, speed_mps.max]");
  ExpectRefused([](Robot* r) { r->speed = {0.0, 0.0}; }, "speed_mps.max must be positive");
  ExpectRefused([](Robot* r) { r->gantry->overhang = -0.1; }, "gantry.overhang must be >= 0");
  ExpectRefused([](Robot* r) { r->gantry->clearance = -0.1; }, "gantry.clearance must be >= 0");
  ExpectRefused([&](Robot* r) { r->gantry->clearance = nan; }, "gantry: a number is not finite");
  ExpectRefused([](Robot* r) { r->arm = Arm{}; }, "a robot is a gantry or an arm, not both");
  ExpectRefused(
      [](Robot* r) {
        r->gantry.reset();
        r->arm = Arm{};
      },
      "arm.reach must be positive");
}

TEST(RobotTest, SaysWhichRangeAStrokeLeaves) {
  const Robot robot = Valid();
  const double r = 0.028575;
  EXPECT_EQ(OutsideRanges(robot, {3.0, 0.0, 0.4 * r, 0.2 * r, 10 * kDegree}, r), "");
  EXPECT_EQ(OutsideRanges(robot, {3.0, 0.0, 0.0, 0.0, 70 * kDegree}, r),
            "elevation 70 deg outside the robot's [0, 60] deg");
  EXPECT_EQ(OutsideRanges(robot, {3.0, 0.0, 0.3 * r, 0.45 * r, 0.0}, r),
            "tip offset 0.5408 r beyond the robot's 0.5 r");
  EXPECT_EQ(OutsideRanges(robot, {3.0, 0.0, 0.0, 0.6 * r, 0.0}, r),
            "tip offset 0.6 r beyond the robot's 0.5 r");
  EXPECT_EQ(OutsideRanges(robot, {9.0, 0.0, 0.0, 0.0, 0.0}, r),
            "cue speed 9 m/s outside the robot's [0, 8] m/s");
}

}  // namespace
}  // namespace billiard::cue
