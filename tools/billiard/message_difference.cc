#include "tools/billiard/message_difference.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <vector>

namespace billiard::cli {

namespace {

// Compares fields in turn and keeps the first that differs.
class Fields {
 public:
  template <class T>
  void Compare(const std::string& name, const T& recorded, const T& replayed) {
    if (!first_ && !Same(recorded, replayed)) first_ = FieldDifference{name, recorded, replayed};
  }

  template <class T, std::size_t N>
  void Compare(const std::string& name, const T (&recorded)[N], const T (&replayed)[N]) {
    for (std::size_t i = 0; i < N; ++i) Compare(Indexed(name, i), recorded[i], replayed[i]);
  }

  // Variable-length arrays: their counts are compared before them, so only a common length is
  // left to walk.
  template <class T>
  void Compare(const std::string& name, const std::vector<T>& recorded,
               const std::vector<T>& replayed) {
    for (std::size_t i = 0; i < std::min(recorded.size(), replayed.size()); ++i) {
      Compare(Indexed(name, i), recorded[i], replayed[i]);
    }
  }

  void Compare(const std::string& name, const ball_state_t& recorded,
               const ball_state_t& replayed) {
    Compare(name + ".utime", recorded.utime, replayed.utime);
    Compare(name + ".ball_id", recorded.ball_id, replayed.ball_id);
    Compare(name + ".position", recorded.position, replayed.position);
    Compare(name + ".velocity", recorded.velocity, replayed.velocity);
    Compare(name + ".spin", recorded.spin, replayed.spin);
    Compare(name + ".covariance", recorded.covariance, replayed.covariance);
  }

  void Compare(const std::string& name, const ball_path_t& recorded, const ball_path_t& replayed) {
    Compare(name + ".ball_id", recorded.ball_id, replayed.ball_id);
    Compare(name + ".num_points", recorded.num_points, replayed.num_points);
    Compare(name + ".points", recorded.points, replayed.points);
  }

  const std::optional<FieldDifference>& first() const { return first_; }

 private:
  static std::string Indexed(const std::string& name, std::size_t i) {
    return name + "[" + std::to_string(i) + "]";
  }
  static bool Same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
  template <class T>
  static bool Same(const T& a, const T& b) {
    return a == b;
  }

  std::optional<FieldDifference> first_;
};

}  // namespace

std::optional<FieldDifference> FirstFieldDifference(const table_state_t& recorded,
                                                    const table_state_t& replayed) {
  Fields f;
  f.Compare("utime", recorded.utime, replayed.utime);
  f.Compare("num_balls", recorded.num_balls, replayed.num_balls);
  f.Compare("balls", recorded.balls, replayed.balls);
  return f.first();
}

std::optional<FieldDifference> FirstFieldDifference(const cue_command_t& recorded,
                                                    const cue_command_t& replayed) {
  Fields f;
  f.Compare("utime", recorded.utime, replayed.utime);
  f.Compare("request_id", recorded.request_id, replayed.request_id);
  f.Compare("ball_id", recorded.ball_id, replayed.ball_id);
  f.Compare("cue_speed", recorded.cue_speed, replayed.cue_speed);
  f.Compare("heading", recorded.heading, replayed.heading);
  f.Compare("tip_side", recorded.tip_side, replayed.tip_side);
  f.Compare("tip_height", recorded.tip_height, replayed.tip_height);
  f.Compare("elevation", recorded.elevation, replayed.elevation);
  f.Compare("v0", recorded.v0, replayed.v0);
  f.Compare("w0", recorded.w0, replayed.w0);
  f.Compare("start", recorded.start, replayed.start);
  f.Compare("num_path_points", recorded.num_path_points, replayed.num_path_points);
  f.Compare("path", recorded.path, replayed.path);
  f.Compare("predicted_final", recorded.predicted_final, replayed.predicted_final);
  f.Compare("closed_form_miss_m", recorded.closed_form_miss_m, replayed.closed_form_miss_m);
  f.Compare("refined_miss_m", recorded.refined_miss_m, replayed.refined_miss_m);
  f.Compare("iterations", recorded.iterations, replayed.iterations);
  f.Compare("mode", recorded.mode, replayed.mode);
  f.Compare("object_ball_id", recorded.object_ball_id, replayed.object_ball_id);
  f.Compare("pocket", recorded.pocket, replayed.pocket);
  f.Compare("kind", recorded.kind, replayed.kind);
  f.Compare("margin_deg", recorded.margin_deg, replayed.margin_deg);
  f.Compare("speed_window", recorded.speed_window, replayed.speed_window);
  f.Compare("cue_rest", recorded.cue_rest, replayed.cue_rest);
  f.Compare("num_ball_paths", recorded.num_ball_paths, replayed.num_ball_paths);
  f.Compare("ball_paths", recorded.ball_paths, replayed.ball_paths);
  f.Compare("status", recorded.status, replayed.status);
  f.Compare("reason", recorded.reason, replayed.reason);
  return f.first();
}

}  // namespace billiard::cli
