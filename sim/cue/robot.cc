#include "sim/cue/robot.h"

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>

namespace billiard::cue {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kRightAngle = M_PI / 2.0;

void Require(bool ok, const std::string& reason) {
  if (!ok) throw std::invalid_argument(reason);
}

bool AllFinite(std::initializer_list<double> values) {
  for (double v : values) {
    if (!std::isfinite(v)) return false;
  }
  return true;
}

void ValidateCue(const Robot& robot) {
  const CueShape& cue = robot.cue;
  Require(cue.length > 0, "cue.length must be positive");
  Require(cue.tip_radius > 0, "cue.tip_radius must be positive");
  Require(cue.butt_radius >= cue.tip_radius, "cue.butt_radius must be at least cue.tip_radius");
  Require(cue.butt_radius < cue.length, "cue.butt_radius must be below cue.length");
  Require(robot.bridge >= 0 && robot.bridge <= cue.length, "bridge must be in [0, cue.length]");
}

void ValidateRanges(const Robot& robot) {
  Require(robot.elevation.min >= 0 && robot.elevation.min <= robot.elevation.max,
          "elevation_deg.min must be in [0, elevation_deg.max]");
  Require(robot.elevation.max < kRightAngle, "elevation_deg.max must be below 90");
  Require(robot.max_tip_offset > 0 && robot.max_tip_offset < 1, "max_tip_offset must be in (0, 1)");
  Require(robot.speed.min >= 0 && robot.speed.min <= robot.speed.max,
          "speed_mps.min must be in [0, speed_mps.max]");
  Require(robot.speed.max > 0, "speed_mps.max must be positive");
}

void ValidateBody(const Robot& robot) {
  Require(!(robot.gantry && robot.arm), "a robot is a gantry or an arm, not both");
  if (robot.gantry) {
    Require(AllFinite({robot.gantry->overhang, robot.gantry->clearance}),
            "gantry: a number is not finite");
    Require(robot.gantry->overhang >= 0, "gantry.overhang must be >= 0");
    Require(robot.gantry->clearance >= 0, "gantry.clearance must be >= 0");
  }
  if (robot.arm) {
    Require(robot.arm->base.allFinite() && std::isfinite(robot.arm->reach),
            "arm: a number is not finite");
    Require(robot.arm->reach > 0, "arm.reach must be positive");
  }
}

}  // namespace

void ValidateRobot(const Robot& robot) {
  Require(AllFinite({robot.cue.length, robot.cue.tip_radius, robot.cue.butt_radius, robot.bridge,
                     robot.elevation.min, robot.elevation.max, robot.max_tip_offset,
                     robot.speed.min, robot.speed.max}),
          "a number is not finite");
  ValidateCue(robot);
  ValidateRanges(robot);
  ValidateBody(robot);
}

std::string OutsideRanges(const Robot& robot, const physics::CueStroke& stroke,
                          double ball_radius) {
  char reason[128] = "";
  const double offset = std::hypot(stroke.tip_side, stroke.tip_height) / ball_radius;
  if (!robot.elevation.Contains(stroke.elevation)) {
    std::snprintf(reason, sizeof reason, "elevation %.4g deg outside the robot's [%.4g, %.4g] deg",
                  stroke.elevation / kDegree, robot.elevation.min / kDegree,
                  robot.elevation.max / kDegree);
  } else if (offset > robot.max_tip_offset) {
    std::snprintf(reason, sizeof reason, "tip offset %.4g r beyond the robot's %.4g r", offset,
                  robot.max_tip_offset);
  } else if (!robot.speed.Contains(stroke.speed)) {
    std::snprintf(reason, sizeof reason, "cue speed %.4g m/s outside the robot's [%.4g, %.4g] m/s",
                  stroke.speed, robot.speed.min, robot.speed.max);
  }
  return reason;
}

}  // namespace billiard::cue
