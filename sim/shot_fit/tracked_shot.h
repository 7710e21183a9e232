// Shots as an overhead camera tracked them: each ball's centre at the times it was seen, on the
// playing surface (origin at a corner, x along the long side, metres), and the ball the cue struck.
//
// The file format (the one of shared/data/real-shots/): a JSON object with an optional string
// "_source" (where the shots come from), an optional object "table" ("length", "width",
// "ball_radius") and the array "shots", each {"id": number or string, "cue_ball": name,
// "balls": {name: {"t": [...], "x": [...], "y": [...]}}}, the times not decreasing.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace billiard::shot_fit {

struct TrackedBall {
  std::string name;
  std::vector<double> t;                  // [s], not decreasing
  std::vector<Eigen::Vector2d> position;  // the centre at t [m]
};

struct TrackedShot {
  std::string id;
  std::size_t cue = 0;  // index in balls of the ball the cue struck
  std::vector<TrackedBall> balls;

  // The last time any ball was seen [s].
  double Duration() const;
  // Samples over all balls.
  std::size_t SampleCount() const;
};

struct TrackedShots {
  std::string source;  // the file's "_source", "" when it has none
  std::optional<double> length, width, ball_radius;  // the file's "table", when given
  std::vector<TrackedShot> shots;
};

// Throws std::invalid_argument with a one-line reason naming the file and the shot on unreadable
// or invalid JSON, a missing key, arrays of different lengths, times that decrease, a
// non-finite number, a shot without balls or a cue ball it does not have.
TrackedShots ParseTrackedShots(const std::string& json_text, const std::string& origin);
TrackedShots ReadTrackedShots(const std::string& path);

// The JSON text of `shots` in the same format (what ParseTrackedShots reads back).
std::string TrackedShotsJson(const TrackedShots& shots);

}  // namespace billiard::shot_fit
