// A break written as a video with its truth, for the camera node's tests: the eight-ball rack
// of a seed broken by the cue ball (sim/table/testing/breaks.h: 7 m/s at the apex, a seeded aim
// and tip error), simulated on the whole table (sim/table/), each frame rendered by the table
// simulator's camera (sim/render/, the balls as table_sim_node shows them:
// sim/table_sim_node/truth_frame.h) and written as MJPG in an AVI (video_files.h); and the
// estimator's TABLE_STATE messages of its frames scored against that truth, as the closed
// loop scores its break (table_sim_node's tracking report).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "lcmtypes/billiard/table_state_t.hpp"
#include "sim/camera/camera_model.h"

namespace billiard::camera_node::testing {

struct BreakVideoOptions {
  int width = 1280, height = 720;  // the table simulator's frames [px]
  double fps = 30.0;               // its camera's rate [Hz]
  double at_rest = 0.3;            // the rack shown still before the strike [s]
  double duration = 1.5;           // of the whole video [s]
  std::uint64_t seed = 1;
};

struct BreakVideo {
  double fps = 0.0;
  camera::CameraModel camera;  // the camera the frames are rendered with
  // Frame k (at k / fps s): each ball on the table, its id and its true centre [m].
  std::vector<std::map<int, Eigen::Vector2d>> truth;
};

// What is also done with each frame as it is written (frame k at t = k / fps): the same frames
// sent another way, to compare.
using FrameTap = std::function<void(const cv::Mat& frame, double t)>;

// Renders the break and writes it to `path` (an .avi).
BreakVideo WriteBreakVideo(const std::string& path, const BreakVideoOptions& options = {},
                           const FrameTap& tap = nullptr);

// The estimator's positions against the truth, over every ball of every frame from
// kSettledFrom on (the tracks confirmed): a ball's error is that of the estimated ball nearest
// it within a ball's radius; a ball with none there is untracked.
struct TrackingScore {
  int frames = 0;       // frames with a state
  int ball_frames = 0;  // balls scored
  int untracked = 0;    // of those, without an estimate within a radius
  double rms_mm = 0.0, max_mm = 0.0;
  // The same over the ball-frames of balls clear of every other (centres more than kClear
  // radii apart), the kind the estimator's benchmark scores (estimator/testing/shot_scenes.h).
  int clear_ball_frames = 0;
  double clear_rms_mm = 0.0, clear_max_mm = 0.0;
};
inline constexpr double kClear = 3.0;
inline constexpr double kSettledFrom = 0.1;  // [s], as the estimator's benchmark

// `states` are the estimator's, their utimes the frames' (the first frame's is `first_utime`).
TrackingScore ScoreAgainstTruth(const BreakVideo& video, const std::vector<table_state_t>& states,
                                std::int64_t first_utime, double ball_radius);

}  // namespace billiard::camera_node::testing
