#include "tools/camera_node/testing/break_video.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/params/parameter_sets.h"
#include "sim/params/table_specs.h"
#include "sim/render/table_renderer.h"
#include "sim/table/table_simulation.h"
#include "sim/table/testing/breaks.h"
#include "sim/table_sim_node/truth_frame.h"
#include "tools/camera_node/testing/video_files.h"

namespace billiard::camera_node::testing {

namespace {

// The parameter set of the closed loop's break (on params::kDefaultTable, as table_sim_node's).
constexpr char kParameters[] = "pool";

}  // namespace

BreakVideo WriteBreakVideo(const std::string& path, const BreakVideoOptions& options,
                           const FrameTap& tap) {
  const physics::ModelParameters params = params::LoadParameters(kParameters);
  const table::TableGeometry geometry =
      table::BuildTable(params::LoadTableSpec(params::kDefaultTable));
  const std::vector<table::SceneBall> scene =
      table::testing::SeededBreak(geometry, params, options.seed);
  table::TableSimulation sim(geometry, params, scene);
  sim.Run(options.duration);

  BreakVideo video;
  video.fps = options.fps;
  video.camera = camera::CameraModel::Overhead(params.table, options.width, options.height);
  const render::TableRenderer renderer(video.camera, params);
  cv::VideoWriter writer =
      OpenMjpgWriter(path, options.fps, cv::Size(options.width, options.height));
  cv::Mat frame;
  for (int k = 0; k / options.fps < options.duration; ++k) {
    const double t = k / options.fps;
    const std::vector<table_sim_node::TruthBall> balls =
        t < options.at_rest ? table_sim_node::AtRest(scene)
                            : table_sim_node::OnTable(sim, options.at_rest, t);
    renderer.Render(table_sim_node::RenderedBalls(balls), t, &frame);
    writer.write(frame);
    if (tap) tap(frame, t);
    std::map<int, Eigen::Vector2d>& truth = video.truth.emplace_back();
    for (const table_sim_node::TruthBall& ball : balls) truth[ball.id] = ball.state(t).head<2>();
  }
  return video;
}

namespace {

// Whether ball `id` of `balls` is more than kClear radii from every other.
bool ClearOfTheOthers(const std::map<int, Eigen::Vector2d>& balls, int id, double radius) {
  for (const auto& [other, at] : balls) {
    if (other != id && (at - balls.at(id)).norm() <= kClear * radius) return false;
  }
  return true;
}

}  // namespace

TrackingScore ScoreAgainstTruth(const BreakVideo& video, const std::vector<table_state_t>& states,
                                std::int64_t first_utime, double ball_radius) {
  TrackingScore score;
  double sum_squares = 0.0, clear_sum_squares = 0.0;
  for (const table_state_t& state : states) {
    const long k = std::lround(1e-6 * (state.utime - first_utime) * video.fps);
    if (k < 0 || k >= static_cast<long>(video.truth.size())) continue;
    ++score.frames;
    if (k / video.fps < kSettledFrom) continue;
    for (const auto& [id, truth] : video.truth[k]) {
      double nearest = std::numeric_limits<double>::infinity();
      for (const ball_state_t& b : state.balls) {
        nearest =
            std::min(nearest, std::hypot(b.position[0] - truth.x(), b.position[1] - truth.y()));
      }
      ++score.ball_frames;
      if (nearest > ball_radius) {
        ++score.untracked;
        continue;
      }
      sum_squares += nearest * nearest;
      score.max_mm = std::max(score.max_mm, 1e3 * nearest);
      if (!ClearOfTheOthers(video.truth[k], id, ball_radius)) continue;
      ++score.clear_ball_frames;
      clear_sum_squares += nearest * nearest;
      score.clear_max_mm = std::max(score.clear_max_mm, 1e3 * nearest);
    }
  }
  const int tracked = score.ball_frames - score.untracked;
  score.rms_mm = tracked > 0 ? 1e3 * std::sqrt(sum_squares / tracked) : 0.0;
  score.clear_rms_mm = score.clear_ball_frames > 0
                           ? 1e3 * std::sqrt(clear_sum_squares / score.clear_ball_frames)
                           : 0.0;
  return score;
}

}  // namespace billiard::camera_node::testing
