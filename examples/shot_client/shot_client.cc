// What a robot sends a running planner_node and what it gets back: the cue ball's state on
// TABLE_STATE (a robot's own vision would publish it; here a ball at rest), a SHOT_REQUEST to
// roll it to a target, and the CUE_COMMAND that answers it, printed as one JSON object.
//
//   shot_client [--lcm-url URL] [--from X,Y] [--to X,Y] [--timeout SECONDS]
//
// Both are sent again every half second until the answer arrives (a planner started a moment
// ago may not be listening yet; it answers a request it has seen with the same command). Exits 0
// with a plan, 3 when the planner refuses (status and reason in the JSON), 1 without an answer,
// 2 for a bad command line.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <optional>
#include <string>

#include "billiard/lcmtypes/billiard/cue_command_t.hpp"
#include "billiard/lcmtypes/billiard/shot_request_t.hpp"
#include "billiard/lcmtypes/billiard/table_state_t.hpp"
#include "billiard/lcmtypes/message_checks.h"
#include "billiard/lcmtypes/names.h"

namespace {

using billiard::cue_command_t;
namespace messages = billiard::messages;

int Usage(const std::string& why) {
  std::cerr << "shot_client: " << why << std::endl;
  return 2;
}

bool ParsePoint(const char* text, double point[2]) {
  char end = 0;
  return std::sscanf(text, "%lf,%lf%c", &point[0], &point[1], &end) == 2;
}

std::int64_t NowUs() {
  return std::chrono::duration_cast<std::chrono::microseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// A JSON string of `text` (a refusal's reason may quote a value).
std::string JsonString(const std::string& text) {
  std::string out = "\"";
  for (char ch : text) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

// The answer to one request id, checked as the nodes check what they receive.
struct Answer {
  std::int64_t request_id;
  std::optional<cue_command_t> command;
  void On(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    cue_command_t c;
    if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, c).empty()) return;
    if (c.request_id == request_id) command = c;
  }
};

}  // namespace

int main(int argc, char** argv) {
  std::string url;  // "": LCM's default, LCM_DEFAULT_URL when set
  double from[2] = {0.5, 0.5}, to[2] = {1.5, 0.8}, timeout_s = 10.0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return Usage("unknown argument or missing value '" + arg + "'");
    const char* value = argv[++i];
    if (arg == "--lcm-url") {
      url = value;
    } else if (arg == "--from" && ParsePoint(value, from)) {
    } else if (arg == "--to" && ParsePoint(value, to)) {
    } else if (arg == "--timeout" && std::sscanf(value, "%lf", &timeout_s) == 1 && timeout_s > 0) {
    } else {
      return Usage("bad " + arg + " '" + value + "'");
    }
  }
  lcm::LCM lcm(url);
  if (!lcm.good()) {
    std::cerr << "shot_client: cannot open LCM" << std::endl;
    return 1;
  }

  // One ball at rest, the cue ball (id 0), where the robot sees it now.
  const std::int64_t utime = NowUs();
  billiard::ball_state_t ball{};
  ball.utime = utime;
  ball.ball_id = 0;
  ball.position[0] = from[0];
  ball.position[1] = from[1];
  ball.ball_class = billiard::ball_state_t::CLASS_CUE;
  ball.class_confidence = 1.0f;
  billiard::table_state_t state{};
  state.utime = utime;
  state.num_balls = 1;
  state.balls = {ball};

  billiard::shot_request_t request{};
  request.utime = utime;
  request.request_id = utime % 1000000000;  // any id of ours; the answer echoes it
  request.ball_id = 0;
  request.target[0] = to[0];
  request.target[1] = to[1];
  request.final_speed = 0.0;  // stop on the target
  request.spin = billiard::shot_request_t::SPIN_NATURAL;

  Answer answer{request.request_id, std::nullopt};
  lcm.subscribe(messages::kCueCommandChannel, &Answer::On, &answer);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!answer.command && std::chrono::steady_clock::now() < deadline) {
    lcm.publish(messages::kTableStateChannel, &state);
    lcm.publish(messages::kShotRequestChannel, &request);
    const auto resend = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    while (!answer.command && std::chrono::steady_clock::now() < resend) lcm.handleTimeout(50);
  }
  if (!answer.command) {
    std::cerr << "shot_client: no CUE_COMMAND from a planner_node within " << timeout_s << " s"
              << std::endl;
    return 1;
  }
  const cue_command_t& c = *answer.command;
  std::cout.precision(6);
  std::cout << "{\"request_id\":" << c.request_id << ",\"status\":" << int(c.status)
            << ",\"reason\":" << JsonString(c.reason) << ",\"cue\":{\"speed\":" << c.cue_speed
            << ",\"heading\":" << c.heading << ",\"tip_side\":" << c.tip_side
            << ",\"tip_height\":" << c.tip_height << ",\"elevation\":" << c.elevation
            << "},\"v0\":[" << c.v0[0] << "," << c.v0[1] << "],\"predicted_final\":["
            << c.predicted_final[0] << "," << c.predicted_final[1]
            << "],\"refined_miss_m\":" << c.refined_miss_m << ",\"solve_us\":" << c.solve_us << "}"
            << std::endl;
  return c.status == cue_command_t::STATUS_OK ? 0 : 3;
}
