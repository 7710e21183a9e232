// A node's health: what it received, refused and published, how long its work took, and its own
// counters, published as node_status_t on NODE_STATUS once a second.
//
// Refusals are logged with their reason, but a flood of bad messages must not become a flood of
// log lines (nor slow the node down writing them): after kLogLinesPerSecond lines in a second the
// rest of that second's refusals are only counted, and the next line says how many were not
// logged.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <lcm/lcm-cpp.hpp>
#include <map>
#include <string>
#include <vector>

#include "lcmtypes/billiard/node_status_t.hpp"

namespace billiard::nodes {

class NodeHealth {
 public:
  using Log = std::function<void(const std::string& line)>;
  using Clock = std::chrono::steady_clock;

  static constexpr int kLogLinesPerSecond = 20;
  static constexpr std::size_t kMaxLatencySamples = 1 << 16;  // per period

  // `log` gets the refusal lines; `period` is how often PublishIfDue publishes.
  NodeHealth(std::string node, Log log, Clock::duration period = std::chrono::seconds(1));

  void Received() { ++received_; }
  void Published() { ++published_; }
  // Counts a refused message and logs why (rate-limited, see above).
  void Dropped(const std::string& why);
  // Counts a message the node read and refused to act on under `counter` (a table simulator's
  // robot refusing a stroke its cue cannot make: "cue_blocked"), the reason its last error,
  // logged as Dropped's are.
  void Refused(const std::string& counter, const std::string& why);
  // Counts an event of the node's own: "duplicate", "stale_state", "busy", ...
  void Count(const std::string& counter, std::int64_t n = 1) { counters_[counter] += n; }
  // A setting of the node's, reported among its counters so that a log of its statuses says how
  // it ran (messages::kRealtimeClockSetting).
  void Set(const std::string& setting, std::int64_t value) { counters_[setting] = value; }
  // The time from a message's arrival to the end of the work it caused.
  void Latency(Clock::duration latency);
  void SetQueueDepth(int depth) { queue_depth_ = depth; }
  // The node's parameter set, announced in every status (node_status_t.params, params_hash)
  // beside the version it was built from (node_status_t.version, always kVersion).
  void SetParameters(std::string name, std::string hash) {
    params_ = std::move(name);
    params_hash_ = std::move(hash);
  }

  std::int64_t received() const { return received_; }
  std::int64_t dropped() const { return dropped_; }
  std::int64_t published() const { return published_; }
  std::int64_t counter(const std::string& name) const;
  const std::string& last_error() const { return last_error_; }

  // The status now. The latency figures are over the period since the previous TakeStatus, and
  // a new period starts.
  node_status_t TakeStatus();

  // Publishes TakeStatus() on NODE_STATUS.
  void Publish(lcm::LCM& lcm);

  // Publishes on the first call, and then when a period has passed since the last status.
  void PublishIfDue(lcm::LCM& lcm);

 private:
  // The latest refusal `why` as the last error, logged after `what` ("dropped: "), at most
  // kLogLinesPerSecond lines a second.
  void Record(const char* what, const std::string& why);
  const std::string node_;
  const Log log_;
  const Clock::duration period_;
  const Clock::time_point start_ = Clock::now();
  bool announced_ = false;
  Clock::time_point last_status_ = start_;
  std::int64_t received_ = 0, dropped_ = 0, published_ = 0;
  std::string params_, params_hash_;
  std::string last_error_;
  std::int64_t last_error_utime_ = 0;
  std::map<std::string, std::int64_t> counters_;
  int queue_depth_ = 0;
  std::vector<double> latencies_us_;
  std::int64_t latency_count_ = 0;
  double latency_max_us_ = 0.0;
  Clock::time_point log_second_ = start_;
  int log_lines_ = 0;
  std::int64_t not_logged_ = 0;
};

}  // namespace billiard::nodes
