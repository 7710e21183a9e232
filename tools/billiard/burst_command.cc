#include "tools/billiard/burst_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "bench/speed_error.h"
#include "lcmtypes/billiard/node_status_t.hpp"
#include "lcmtypes/billiard/shot_request_t.hpp"
#include "lcmtypes/billiard/table_state_t.hpp"
#include "lcmtypes/message_checks.h"
#include "lcmtypes/names.h"
#include "lcmtypes/node/node_health.h"
#include "lcmtypes/node/node_loop.h"
#include "planner/node/planner_node.h"
#include "tools/billiard/command_line.h"

namespace billiard::cli {

namespace {

using Clock = std::chrono::steady_clock;

// The longest wait for the planner's answer to the probe before the burst [s].
constexpr double kProbeSeconds = 10.0;

struct BurstArgs {
  std::string lcm_url;
  int requests = 10000;
  double x = 0.6, y = 0.635;  // the ball [m]
  double timeout = 60.0;      // [s]
  double state_age = 0.0;     // how much older the ball's state is than the requests [s]
  bool json = false;
};

// What comes back, by request_id (0 is the probe that the planner is up).
struct Replies {
  std::vector<Clock::time_point> sent;
  std::vector<std::optional<Clock::time_point>> answered;
  std::map<std::string, long> statuses;
  long answers = 0, repeated = 0, malformed = 0;
  std::optional<node_status_t> planner_status;

  void OnCommand(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    const Clock::time_point now = Clock::now();
    cue_command_t c;
    if (!messages::DecodeChecked(rbuf->data, rbuf->data_size, c).empty() || c.request_id < 0 ||
        c.request_id >= static_cast<std::int64_t>(answered.size())) {
      ++malformed;
      return;
    }
    ++answers;
    if (answered[c.request_id]) {
      ++repeated;
      return;
    }
    answered[c.request_id] = now;
    ++statuses[messages::CueCommandStatusName(c.status)];
  }

  void OnStatus(const lcm::ReceiveBuffer* rbuf, const std::string&) {
    node_status_t s;
    if (messages::DecodeChecked(rbuf->data, rbuf->data_size, s).empty() &&
        s.node == "planner_node") {
      planner_status = s;
    }
  }
};

void Run(const BurstArgs& args) {
  if (args.requests < 1) throw UsageError("--requests must be at least 1");
  if (!(args.timeout > 0.0)) throw UsageError("--timeout must be a positive number of seconds");
  nodes::WarnAboutTheReceiveBuffer("billiard burst", args.lcm_url);
  lcm::LCM lcm(args.lcm_url);
  if (!lcm.good()) throw std::runtime_error("cannot initialise LCM");
  Replies replies;
  const std::size_t total = static_cast<std::size_t>(args.requests) + 1;
  replies.sent.resize(total);
  replies.answered.resize(total);
  // Every answer must find room: the burst's answers arrive faster than they are handled.
  lcm.subscribe(messages::kCueCommandChannel, &Replies::OnCommand, &replies)
      ->setQueueCapacity(static_cast<int>(total) + 100);
  lcm.subscribe(messages::kNodeStatusChannel, &Replies::OnStatus, &replies);

  const std::int64_t utime = std::chrono::duration_cast<std::chrono::microseconds>(
                                 std::chrono::system_clock::now().time_since_epoch())
                                 .count();
  table_state_t state{};
  state.utime = utime - static_cast<std::int64_t>(1e6 * args.state_age);
  ball_state_t ball{};
  ball.utime = state.utime;
  ball.position[0] = args.x;
  ball.position[1] = args.y;
  state.balls = {ball};
  state.num_balls = 1;
  const auto request = [&](std::int64_t id) {
    shot_request_t q{};
    q.utime = utime;
    q.request_id = id;
    q.target[0] = args.x + 0.8;
    q.target[1] = args.y - 0.2 + 0.4 * static_cast<double>(id) / static_cast<double>(total);
    return q;
  };
  const auto handle_until = [&](const std::function<bool()>& done, double seconds) {
    const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                          std::chrono::duration<double>(seconds));
    while (!done() && Clock::now() < deadline) lcm.handleTimeout(20);
  };

  // The probe: the state, then one request, until the planner answers it. --timeout bounds this
  // wait too, so that a short one checks quickly whether a planner is up.
  const double probe_s = std::min(kProbeSeconds, args.timeout);
  const Clock::time_point start = Clock::now();
  while (!replies.answered[0] && Clock::now() - start < std::chrono::duration<double>(probe_s)) {
    lcm.publish(messages::kTableStateChannel, &state);
    const shot_request_t probe = request(0);
    replies.sent[0] = Clock::now();
    lcm.publish(messages::kShotRequestChannel, &probe);
    handle_until([&] { return replies.answered[0].has_value(); }, 0.5);
  }
  if (!replies.answered[0]) {
    std::ostringstream reason;
    reason << "no planner_node answered within " << probe_s << " s";
    throw std::runtime_error(reason.str());
  }
  replies.statuses.clear();

  std::cerr << "burst: " << args.requests << " requests" << std::endl;
  const Clock::time_point burst_start = Clock::now();
  for (std::int64_t id = 1; id < static_cast<std::int64_t>(total); ++id) {
    const shot_request_t q = request(id);
    replies.sent[id] = Clock::now();
    lcm.publish(messages::kShotRequestChannel, &q);
  }
  const double send_s = std::chrono::duration<double>(Clock::now() - burst_start).count();
  long answered = 0;
  handle_until(
      [&] {
        answered = std::count_if(replies.answered.begin() + 1, replies.answered.end(),
                                 [](const auto& a) { return a.has_value(); });
        return answered == args.requests;
      },
      args.timeout);
  const double total_s = std::chrono::duration<double>(Clock::now() - burst_start).count();
  // The planner's next status says what the burst did to it.
  const std::int64_t status_after = utime + static_cast<std::int64_t>(1e6 * total_s);
  handle_until(
      [&] { return replies.planner_status && replies.planner_status->utime > status_after; }, 2.5);

  std::vector<double> latency_ms;
  for (std::size_t id = 1; id < total; ++id) {
    if (replies.answered[id]) {
      latency_ms.push_back(
          std::chrono::duration<double, std::milli>(*replies.answered[id] - replies.sent[id])
              .count());
    }
  }
  nlohmann::json j = {
      {"requests", args.requests},
      {"answered", answered},
      {"unanswered", args.requests - answered},
      {"answered_twice", replies.repeated},
      {"malformed_answers", replies.malformed},
      {"statuses", replies.statuses},
      {"send_s", send_s},
      {"total_s", total_s},
      {"latency_ms",
       {{"p50", bench::Quantile(latency_ms, 0.5)},
        {"p99", bench::Quantile(latency_ms, 0.99)},
        {"max",
         latency_ms.empty() ? 0.0 : *std::max_element(latency_ms.begin(), latency_ms.end())}}}};
  if (replies.planner_status) {
    const node_status_t& s = *replies.planner_status;
    j["planner_status"] = {{"received", s.received},
                           {"dropped", s.dropped},
                           {"published", s.published},
                           {"queue_depth", s.queue_depth},
                           {"latency_p50_us", s.latency_p50_us},
                           {"latency_p99_us", s.latency_p99_us},
                           {"latency_max_us", s.latency_max_us}};
  }
  if (args.json) std::cout << j.dump() << std::endl;
  std::cerr << "burst: " << answered << " of " << args.requests << " answered in " << total_s
            << " s (sent in " << send_s << " s); " << j["statuses"].dump() << "; latency p50 "
            << bench::Quantile(latency_ms, 0.5) << " ms, p99 " << bench::Quantile(latency_ms, 0.99)
            << " ms" << std::endl;
  if (answered != args.requests) {
    throw std::runtime_error(std::to_string(args.requests - answered) + " requests got no answer");
  }
}

}  // namespace

void AddBurstCommand(CLI::App& app) {
  auto args = std::make_shared<BurstArgs>();
  CLI::App* cmd = app.add_subcommand(
      "burst",
      "Send a burst of shot requests to a running planner_node and report what came back (exit 1 "
      "if the planner or any request got no answer)");
  cmd->add_option("--requests", args->requests, "Requests in the burst")->capture_default_str();
  cmd->add_option("--lcm-url", args->lcm_url, "LCM URL (default: $LCM_DEFAULT_URL)");
  cmd->add_option("--timeout", args->timeout,
                  "Longest wait for the answers [s], and for the planner's first (at most 10 s)")
      ->capture_default_str();
  cmd->add_option("--state-age", args->state_age,
                  "Stamp the ball's state this much before the requests [s]: beyond the planner's "
                  "--max-state-age every answer must be stale_state")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", args->json, "Print the figures as JSON on stdout");
  cmd->callback([args] { Run(*args); });
}

}  // namespace billiard::cli
