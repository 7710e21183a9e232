#include "sim/cue/clearance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "sim/cue/body.h"
#include "sim/cue/placed_cue.h"
#include "sim/cue/rod_distance.h"
#include "sim/cue/table_obstacles.h"

namespace billiard::cue {

namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kMillimetre = 1e-3;
// The scan's step up the elevation range, and the bisection's resolution [rad].
constexpr double kScanStep = 0.5 * kDegree;
constexpr double kElevationResolution = 1e-9;

const table::SceneBall& CueBall(const std::vector<table::SceneBall>& balls, int cue_ball_id) {
  const auto found = std::find_if(balls.begin(), balls.end(),
                                  [&](const table::SceneBall& b) { return b.id == cue_ball_id; });
  if (found == balls.end()) {
    throw std::invalid_argument("no ball " + std::to_string(cue_ball_id) + " to strike");
  }
  return *found;
}

// Keeps `candidate` in `nearest` when it comes nearer.
void Nearer(const CueClearance& candidate, CueClearance* nearest) {
  if (candidate.distance < nearest->distance) *nearest = candidate;
}

// The nearest of the balls other than the cue ball.
void NearestBall(const PlacedCue& cue, double ball_radius,
                 const std::vector<table::SceneBall>& balls, int cue_ball_id,
                 CueClearance* nearest) {
  for (const table::SceneBall& ball : balls) {
    if (ball.id == cue_ball_id) continue;
    const Eigen::Vector3d centre(ball.state[0], ball.state[1], ball_radius);
    double along = 0;
    const double distance = DistanceToBall(cue, centre, ball_radius, &along);
    Nearer({false, Obstacle::kBall, ball.id, "ball " + std::to_string(ball.id), distance, along}, nearest);
  }
}

// The cue ball's clearance at `elevation`, the stroke's heading and offsets kept.
CueClearance ClearanceAt(double elevation, const table::TableGeometry& table, double ball_radius,
                         const std::vector<table::SceneBall>& balls, int cue_ball_id,
                         physics::CueStroke stroke, const Robot& robot) {
  stroke.elevation = elevation;
  return Clearance(table, ball_radius, balls, cue_ball_id, stroke, robot);
}

std::string NothingClears(const Robot& robot, const CueClearance& top) {
  char reason[256];
  std::snprintf(reason, sizeof reason,
                "nothing in the robot's elevations [%.3g, %.3g] deg clears: at %.3g deg %s ",
                robot.elevation.min / kDegree, robot.elevation.max / kDegree,
                robot.elevation.max / kDegree, top.what.c_str());
  char depth[64] = "touches the cue";
  if (top.distance < 0) {
    std::snprintf(depth, sizeof depth, "is %.3g mm into the cue", -top.distance / kMillimetre);
  }
  return std::string(reason) + depth;
}

}  // namespace

CueClearance Clearance(const table::TableGeometry& table, double ball_radius,
                       const std::vector<table::SceneBall>& balls, int cue_ball_id,
                       const physics::CueStroke& stroke, const Robot& robot) {
  const table::SceneBall& cue_ball = CueBall(balls, cue_ball_id);
  const PlacedCue cue =
      PlaceCue({cue_ball.state[0], cue_ball.state[1]}, ball_radius, stroke, robot.cue);
  CueClearance nearest;
  NearestBall(cue, ball_radius, balls, cue_ball_id, &nearest);
  for (const TableObstacle& obstacle : TableObstacles(table)) {
    double along = 0;
    const double distance = DistanceToBox(cue, obstacle.box, &along);
    Nearer({false, Obstacle::kTable, -1, obstacle.name, distance, along}, &nearest);
  }
  const BodyMargin body = BodyClearance(table, cue, robot);
  Nearer({false, Obstacle::kBody, -1, body.what, body.distance, body.along}, &nearest);
  nearest.clears = nearest.distance > 0;
  return nearest;
}

ClearingElevation LeastClearingElevation(const table::TableGeometry& table, double ball_radius,
                                         const std::vector<table::SceneBall>& balls,
                                         int cue_ball_id, const physics::CueStroke& stroke,
                                         const Robot& robot) {
  const auto at = [&](double elevation) {
    return ClearanceAt(elevation, table, ball_radius, balls, cue_ball_id, stroke, robot);
  };
  // Step 1, the scan: the first elevation up the range that clears, and the one below it.
  double blocked = robot.elevation.min, clear = blocked;
  CueClearance found = at(clear);
  while (!found.clears) {
    if (clear == robot.elevation.max) return {std::nullopt, NothingClears(robot, found), found};
    blocked = clear;
    clear = std::min(clear + kScanStep, robot.elevation.max);
    found = at(clear);
  }
  // Step 2, the bisection between them, keeping the clear end.
  while (clear - blocked > kElevationResolution) {
    const double middle = 0.5 * (blocked + clear);
    const CueClearance there = at(middle);
    if (there.clears) {
      clear = middle, found = there;
    } else {
      blocked = middle;
    }
  }
  return {clear, "", found};
}

}  // namespace billiard::cue
