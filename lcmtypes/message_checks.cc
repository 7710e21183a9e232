#include "lcmtypes/message_checks.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <set>
#include <sstream>

namespace billiard::messages {

namespace {

// Reads the wire layout of a payload without decoding it: LCM's big-endian integers, fixed-size
// fields skipped, counts and strings checked against the bytes that remain. A failed read sets
// the error and every later read fails too, so a walk is written straight through and checked
// once at the end.
class WireWalk {
 public:
  WireWalk(const void* data, std::size_t size)
      : bytes_(static_cast<const std::uint8_t*>(data)), size_(size) {}

  void Skip(std::size_t n, const char* what) {
    if (!error_.empty()) return;
    if (n > size_ - pos_) return Fail(std::string(what) + " is cut short");
    pos_ += n;
  }

  // An int32 count of elements of `element_size` bytes each, which must all fit in the payload.
  std::int32_t Count(std::int64_t element_size, std::int64_t max_count, const char* what) {
    const std::int32_t n = Int32(what);
    if (!error_.empty()) return 0;
    if (n < 0 || n > max_count) {
      Fail(std::string(what) + " is " + std::to_string(n) + " (0.." + std::to_string(max_count) +
           ")");
      return 0;
    }
    if (n * element_size > static_cast<std::int64_t>(size_ - pos_)) {
      Fail(std::string(what) + " is " + std::to_string(n) + ", more than the payload holds");
      return 0;
    }
    return n;
  }

  // LCM's string: an int32 length counting the terminating NUL, then the bytes.
  void String(const char* what) {
    const std::int32_t length = Int32(what);
    if (!error_.empty()) return;
    if (length < 1 || length > kMaxReasonLength + 1 ||
        static_cast<std::size_t>(length) > size_ - pos_) {
      return Fail(std::string(what) + " has length " + std::to_string(length) +
                  ", which the payload cannot hold");
    }
    if (bytes_[pos_ + length - 1] != 0) return Fail(std::string(what) + " is not terminated");
    // LCM strings are C strings: lcm-gen's encoders (strlen) and its C decoder end them at the
    // first NUL, so a string with one inside would be forwarded or logged as another message.
    if (std::memchr(bytes_ + pos_, 0, length - 1) != nullptr) {
      return Fail(std::string(what) + " has a NUL before its end");
    }
    pos_ += length;
  }

  const std::string& error() const { return error_; }

 private:
  std::int32_t Int32(const char* what) {
    if (!error_.empty()) return 0;
    if (size_ - pos_ < 4) {
      Fail(std::string(what) + " is cut short");
      return 0;
    }
    const std::uint8_t* b = bytes_ + pos_;
    pos_ += 4;
    return static_cast<std::int32_t>(std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 |
                                     std::uint32_t{b[2]} << 8 | std::uint32_t{b[3]});
  }
  void Fail(std::string why) { error_ = std::move(why); }

  const std::uint8_t* bytes_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string error_;
};

constexpr std::size_t kHash = 8, kInt64 = 8, kInt32 = 4, kDouble = 8, kInt8 = 1;

// The walk of each type with a variable part, in the order of its .lcm file.
std::string WalkLayout(WireWalk& w, const table_state_t*) {
  w.Skip(kHash + kInt64, "table_state_t header");
  w.Count(ball_state_t{}._getEncodedSizeNoHash(), kMaxBalls, "num_balls");
  return w.error();
}

std::string WalkLayout(WireWalk& w, const cue_command_t*) {
  w.Skip(kHash + 2 * kInt64 + kInt32 + (5 + 2 + 3 + 2) * kDouble, "cue_command_t header");
  const std::int32_t points = w.Count(2 * kDouble, kMaxPathPoints, "num_path_points");
  w.Skip(points * 2 * kDouble + 5 * kDouble + kInt32 + kInt8 + kInt32, "cue_command_t plan");
  w.String("pocket");
  w.Skip(kInt8 + 6 * kDouble, "cue_command_t pot");
  // A ball path is at least its id and its count.
  const std::int32_t paths = w.Count(2 * kInt32, kMaxBallPaths, "num_ball_paths");
  for (std::int32_t i = 0; i < paths; ++i) {
    w.Skip(kInt32, "ball path");
    w.Skip(w.Count(2 * kDouble, kMaxPathPoints, "ball path num_points") * 2 * kDouble,
           "ball path points");
  }
  w.Skip(2 * kDouble + kInt8 + 2 * kDouble, "cue_command_t choice");
  w.Skip(kInt8, "cue_command_t status");
  w.String("reason");
  w.Skip(kInt8, "cue_command_t safety");
  return w.error();
}

std::string WalkLayout(WireWalk& w, const image_t*) {
  w.Skip(kHash + kInt64 + 4 * kInt32, "image_t header");
  w.Count(1, kMaxImageBytes, "image size");
  return w.error();
}

std::string WalkLayout(WireWalk& w, const node_status_t*) {
  w.Skip(kHash + kInt64, "node_status_t header");
  w.String("node");
  w.Skip(kInt64, "node_status_t uptime");
  w.String("params");
  w.String("params_hash");
  w.String("version");
  w.Skip(3 * kInt64, "node_status_t counts");
  w.String("last_error");
  w.Skip(kInt64 + kInt32 + 3 * kDouble + kInt32, "node_status_t latency");
  const std::int32_t n = w.Count(kInt32 + 1 + kInt64, 1024, "num_counters");
  for (std::int32_t i = 0; i < n; ++i) w.String("counter name");
  w.Skip(n * kInt64, "counter values");
  return w.error();
}

std::string WalkLayout(WireWalk& w, const shot_request_t*) {
  w.Skip(kHash + 2 * kInt64 + kInt32 + kInt8 + 3 * kDouble + kInt8 + 2 * kDouble + kInt8 + kInt32 +
             kInt8,
         "shot_request_t header");
  w.String("pocket");
  w.Skip(2 * kInt8 + 3 * kDouble + 2 * kInt8, "shot_request_t pot and choice");
  w.String("player");
  return w.error();
}

template <class Message>
std::string DecodeWhole(const void* data, std::size_t size, Message& out, const char* type) {
  if (size > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    return std::string("a ") + std::to_string(size) + "-byte payload is too large for " + type;
  }
  WireWalk walk(data, size);
  if (std::string why = WalkLayout(walk, &out); !why.empty()) {
    return std::to_string(size) + " bytes that are not a " + type + ": " + why;
  }
  const int length = static_cast<int>(size);
  if (out.decode(data, 0, length) != length) {
    return std::to_string(size) + " bytes that do not decode as " + type +
           " (another type, or cut short, or with bytes after it)";
  }
  return {};
}

bool Finite(const double* x, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(x[i])) return false;
  }
  return true;
}

std::string Utime(std::int64_t utime, const char* what) {
  return utime < 0 ? std::string(what) + " utime " + std::to_string(utime) + " is negative"
                   : std::string();
}

// CLASS_UNKNOWN, pool's numbers 1-15, the cue ball or a named colour.
bool KnownBallClass(std::int8_t c) {
  return (c >= ball_state_t::CLASS_UNKNOWN && c <= ball_state_t::CLASS_CUE) ||
         (c >= ball_state_t::CLASS_RED && c <= ball_state_t::CLASS_BLACK);
}

std::string CheckBall(const ball_state_t& b) {
  const std::string ball = "ball " + std::to_string(b.ball_id);
  if (b.ball_id < 0) return "negative ball_id " + std::to_string(b.ball_id);
  if (std::string why = Utime(b.utime, ball.c_str()); !why.empty()) return why;
  if (!Finite(b.position, 2) || !Finite(b.velocity, 2) || !Finite(b.spin, 3)) {
    return ball + " has a non-finite position, velocity or spin";
  }
  if (!Finite(b.covariance, 49)) return ball + " has a non-finite covariance";
  for (int i = 0; i < 7; ++i) {
    if (b.covariance[8 * i] < 0.0) return ball + " has a negative variance";
  }
  if (std::abs(b.position[0]) > kMaxPosition || std::abs(b.position[1]) > kMaxPosition) {
    return ball + " is more than " + std::to_string(kMaxPosition) + " m from the origin";
  }
  if (std::hypot(b.velocity[0], b.velocity[1]) > kMaxSpeed) {
    return ball + " is faster than " + std::to_string(kMaxSpeed) + " m/s";
  }
  if (std::sqrt(b.spin[0] * b.spin[0] + b.spin[1] * b.spin[1] + b.spin[2] * b.spin[2]) > kMaxSpin) {
    return ball + " spins faster than " + std::to_string(kMaxSpin) + " rad/s";
  }
  if (!KnownBallClass(b.ball_class)) {
    return ball + " has an unknown ball_class " + std::to_string(b.ball_class);
  }
  if (!(b.class_confidence >= 0.0f && b.class_confidence <= 1.0f)) {
    return ball + " has a class_confidence outside [0, 1]";
  }
  return {};
}

bool KnownPotKind(std::int8_t kind) {
  return kind >= shot_request_t::KIND_ANY && kind <= shot_request_t::KIND_CURVE;
}

// The object ball is named as the struck ball is: an id, or a known class.
std::string CheckPotRequest(const shot_request_t& m) {
  if (m.object_ball_id == shot_request_t::BALL_BY_CLASS) {
    if (m.object_ball_class == ball_state_t::CLASS_UNKNOWN ||
        !KnownBallClass(m.object_ball_class)) {
      return "an object ball by class needs a known object_ball_class, not " +
             std::to_string(m.object_ball_class);
    }
  } else if (m.object_ball_id < 0) {
    return "negative object_ball_id " + std::to_string(m.object_ball_id);
  }
  if (m.pocket.empty()) return "a pot request without a pocket";
  if (!KnownPotKind(m.kind)) {
    return "unknown kind " + std::to_string(m.kind) + " (0-4, see shot_request_t)";
  }
  if (m.has_cue_target != 0 && m.has_cue_target != 1) {
    return "has_cue_target is " + std::to_string(m.has_cue_target) + ", not 0 or 1";
  }
  if (m.has_cue_target == 1) {
    if (!Finite(m.cue_target, 2) || !std::isfinite(m.cue_radius)) {
      return "request has a non-finite cue-ball target";
    }
    if (m.cue_radius < 0.0 || m.cue_radius > kMaxPosition) {
      std::ostringstream why;
      why << "cue_radius " << m.cue_radius << " m is outside 0.." << kMaxPosition;
      return why.str();
    }
  }
  return {};
}

// A choice: known rules, ball in hand a flag.
std::string CheckChoiceRequest(const shot_request_t& m) {
  if (m.rules < shot_request_t::RULES_ANY || m.rules > shot_request_t::RULES_EIGHT_BALL_STRIPES) {
    return "unknown rules " + std::to_string(m.rules) + " (0-4, see shot_request_t)";
  }
  if (m.ball_in_hand != 0 && m.ball_in_hand != 1) {
    return "ball_in_hand is " + std::to_string(m.ball_in_hand) + ", not 0 or 1";
  }
  return {};
}

// A pot's prediction: finite, a window that is one, the kind a chosen one, one path a ball.
std::string CheckPotCommand(const cue_command_t& m) {
  const std::string command = "command " + std::to_string(m.request_id);
  const double pot[] = {m.margin_deg[0],   m.margin_deg[1], m.speed_window[0],
                        m.speed_window[1], m.cue_rest[0],   m.cue_rest[1]};
  if (!Finite(pot, 6)) return command + " has a non-finite margin, speed window or cue rest";
  const double choice[] = {m.success_probability, m.probability_stderr, m.cue_placement[0],
                           m.cue_placement[1]};
  if (!Finite(choice, 4)) return command + " has a non-finite probability or cue placement";
  if (m.success_probability < 0.0 || m.success_probability > 1.0 || m.probability_stderr < 0.0) {
    return command + " has a probability outside 0..1 or a negative standard error";
  }
  if (m.has_cue_placement != 0 && m.has_cue_placement != 1) {
    return command + " has has_cue_placement " + std::to_string(m.has_cue_placement) +
           ", not 0 or 1";
  }
  if (m.mode < shot_request_t::MODE_TO_POINT || m.mode > shot_request_t::MODE_BREAK) {
    return command + " has an unknown mode " + std::to_string(m.mode);
  }
  if (m.safety != 0 && m.safety != 1) {
    return command + " has safety " + std::to_string(m.safety) + ", not 0 or 1";
  }
  if (!KnownPotKind(m.kind)) return command + " has an unknown kind " + std::to_string(m.kind);
  // A decoded message has its counts by construction; one about to be sent must have them too,
  // within what a receiver decodes (lcm-gen's encoder writes as many as the count says).
  if (m.num_ball_paths != static_cast<std::int32_t>(m.ball_paths.size()) ||
      m.ball_paths.size() > static_cast<std::size_t>(kMaxBallPaths)) {
    return command + " has " + std::to_string(m.ball_paths.size()) +
           " ball paths, num_ball_paths " + std::to_string(m.num_ball_paths) + " (at most " +
           std::to_string(kMaxBallPaths) + ")";
  }
  std::set<std::int32_t> ids;
  for (const ball_path_t& path : m.ball_paths) {
    if (path.num_points != static_cast<std::int32_t>(path.points.size()) ||
        path.points.size() > static_cast<std::size_t>(kMaxPathPoints)) {
      return command + " has a path of ball " + std::to_string(path.ball_id) + " of " +
             std::to_string(path.points.size()) + " points, num_points " +
             std::to_string(path.num_points) + " (at most " + std::to_string(kMaxPathPoints) + ")";
    }
    if (path.ball_id < 0 || !ids.insert(path.ball_id).second) {
      return command + " has a path of ball " + std::to_string(path.ball_id) +
             " (negative, or twice)";
    }
    for (const std::vector<double>& p : path.points) {
      if (!Finite(p.data(), 2)) return command + " has a non-finite ball path";
    }
  }
  if (m.status == cue_command_t::STATUS_OK && m.mode == shot_request_t::MODE_POT &&
      (m.kind == shot_request_t::KIND_ANY || m.margin_deg[0] < 0.0 || m.margin_deg[1] < 0.0 ||
       !(m.speed_window[0] <= m.speed_window[1]))) {
    return "an ok pot " + std::to_string(m.request_id) +
           " without a kind, or with a negative margin or an empty speed window";
  }
  return {};
}

}  // namespace

std::string Decode(const void* data, std::size_t size, table_state_t& out) {
  return DecodeWhole(data, size, out, "table_state_t");
}
std::string Decode(const void* data, std::size_t size, shot_request_t& out) {
  return DecodeWhole(data, size, out, "shot_request_t");
}
std::string Decode(const void* data, std::size_t size, cue_command_t& out) {
  return DecodeWhole(data, size, out, "cue_command_t");
}
std::string Decode(const void* data, std::size_t size, image_t& out) {
  return DecodeWhole(data, size, out, "image_t");
}
std::string Decode(const void* data, std::size_t size, node_status_t& out) {
  return DecodeWhole(data, size, out, "node_status_t");
}

std::string Check(const table_state_t& m) {
  if (std::string why = Utime(m.utime, "table state"); !why.empty()) return why;
  std::set<std::int32_t> ids;
  for (const ball_state_t& b : m.balls) {
    if (std::string why = CheckBall(b); !why.empty()) return why;
    if (b.utime > m.utime) {
      return "ball " + std::to_string(b.ball_id) + " is newer than the table state holding it";
    }
    if (!ids.insert(b.ball_id).second) {
      return "ball " + std::to_string(b.ball_id) + " appears twice";
    }
  }
  return {};
}

std::string Check(const shot_request_t& m) {
  if (std::string why = Utime(m.utime, "request"); !why.empty()) return why;
  if (m.request_id < 0) return "negative request_id " + std::to_string(m.request_id);
  if (m.ball_id == shot_request_t::BALL_BY_CLASS) {
    if (m.ball_class == ball_state_t::CLASS_UNKNOWN || !KnownBallClass(m.ball_class)) {
      return "a ball by class needs a known ball_class, not " + std::to_string(m.ball_class);
    }
  } else if (m.ball_id < 0) {
    return "negative ball_id " + std::to_string(m.ball_id);
  }
  if (m.spin < shot_request_t::SPIN_NATURAL || m.spin > shot_request_t::SPIN_SLIDE) {
    return "unknown spin value " + std::to_string(m.spin) + " (0-4, see shot_request_t)";
  }
  // slide_length means something only with SPIN_SLIDE, so only then must it be a number.
  if (!Finite(m.target, 2) || !std::isfinite(m.final_speed) || !std::isfinite(m.side_spin) ||
      (m.spin == shot_request_t::SPIN_SLIDE && !std::isfinite(m.slide_length))) {
    return "request has a non-finite number";
  }
  if (m.final_speed < 0.0 || m.final_speed > kMaxSpeed) {
    std::ostringstream why;
    why << "final_speed " << m.final_speed << " m/s is outside 0.." << kMaxSpeed;
    return why.str();
  }
  if (std::abs(m.side_spin) > kMaxSpin) {
    return "side_spin is more than " + std::to_string(kMaxSpin) + " rad/s";
  }
  if (m.mode == shot_request_t::MODE_POT) return CheckPotRequest(m);
  if (m.mode == shot_request_t::MODE_CHOOSE) return CheckChoiceRequest(m);
  // A break is a game's: nine-ball's or eight-ball's rack.
  if (m.mode == shot_request_t::MODE_BREAK && m.rules != shot_request_t::RULES_NINE_BALL &&
      m.rules != shot_request_t::RULES_EIGHT_BALL) {
    return "a break under rules " + std::to_string(m.rules) + " (nine-ball 1 or eight-ball 2)";
  }
  if (m.mode < shot_request_t::MODE_TO_POINT || m.mode > shot_request_t::MODE_BREAK) {
    return "unknown mode " + std::to_string(m.mode) + " (0-3, see shot_request_t)";
  }
  return {};
}

std::string Check(const cue_command_t& m) {
  if (std::string why = Utime(m.utime, "command"); !why.empty()) return why;
  if (m.request_id < 0) return "negative request_id " + std::to_string(m.request_id);
  if (m.status < cue_command_t::STATUS_OK || m.status > cue_command_t::STATUS_CUE_BLOCKED) {
    return "unknown status " + std::to_string(m.status);
  }
  const double stroke[] = {m.cue_speed, m.heading, m.tip_side, m.tip_height, m.elevation};
  const double plan[] = {m.predicted_final[0], m.predicted_final[1], m.closed_form_miss_m,
                         m.refined_miss_m, m.solve_us};
  if (!Finite(stroke, 5) || !Finite(m.v0, 2) || !Finite(m.w0, 3) || !Finite(m.start, 2) ||
      !Finite(plan, 5)) {
    return "command " + std::to_string(m.request_id) + " has a non-finite number";
  }
  for (const std::vector<double>& p : m.path) {
    if (!Finite(p.data(), 2)) {
      return "command " + std::to_string(m.request_id) + " has a non-finite path";
    }
  }
  if (std::string why = CheckPotCommand(m); !why.empty()) return why;
  if (m.status == cue_command_t::STATUS_OK) {
    if (!(m.cue_speed > 0.0)) return "an ok command with cue_speed " + std::to_string(m.cue_speed);
    if (!m.reason.empty()) return "an ok command with a reason";
  } else if (m.cue_speed != 0.0) {
    return "a refused command that would move the cue";
  }
  return {};
}

std::string Check(const image_t& m) {
  if (std::string why = Utime(m.utime, "frame"); !why.empty()) return why;
  if (m.width < 1 || m.width > kMaxImageSide || m.height < 1 || m.height > kMaxImageSide) {
    return "a " + std::to_string(m.width) + "x" + std::to_string(m.height) + " frame";
  }
  if (m.row_stride < 0) return "negative row_stride " + std::to_string(m.row_stride);
  return {};
}

std::string Check(const node_status_t& m) {
  if (std::string why = Utime(m.utime, "status"); !why.empty()) return why;
  if (m.node.empty()) return "a status without a node name";
  if (m.uptime_us < 0 || m.received < 0 || m.dropped < 0 || m.published < 0 ||
      m.latency_count < 0 || m.queue_depth < 0) {
    return "a status with a negative count";
  }
  const double latency[] = {m.latency_p50_us, m.latency_p99_us, m.latency_max_us};
  if (!Finite(latency, 3)) return "a status with a non-finite latency";
  return {};
}

}  // namespace billiard::messages
